//! Catalogue source text and positions.  Every load problem is a [`LoadError`]: with a
//! position, `file:line:column: message` followed by the offending source line with the
//! bad text underlined; about a whole file or directory, `file: message` on one line.

use crate::claims::ast::Span;
use std::sync::Arc;
use toml::Spanned;

/// A load error with its position (line 0: the error concerns the whole file).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadError {
    /// File (or directory) name as given.
    pub file: String,
    /// 1-based line; 0 when the error has no position.
    pub line: usize,
    /// 1-based column (characters); 0 when the error has no position.
    pub col: usize,
    /// What is wrong.
    pub message: String,
    /// The source line (empty when it cannot be shown).
    pub line_text: String,
    /// Number of characters to underline.
    pub width: usize,
}

impl LoadError {
    /// An error about a whole file or directory (no position).
    pub fn whole(file: impl Into<String>, message: impl Into<String>) -> Self {
        LoadError {
            file: file.into(),
            line: 0,
            col: 0,
            message: message.into(),
            line_text: String::new(),
            width: 0,
        }
    }
}

impl std::fmt::Display for LoadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.line == 0 {
            return write!(f, "{}: {}", self.file, self.message);
        }
        write!(
            f,
            "{}:{}:{}: {}",
            self.file, self.line, self.col, self.message
        )?;
        if self.line_text.trim().is_empty() {
            return Ok(());
        }
        write!(
            f,
            "\n    {}\n    {}{}",
            self.line_text,
            " ".repeat(self.col.saturating_sub(1)),
            "^".repeat(self.width.max(1))
        )
    }
}

impl std::error::Error for LoadError {}

/// A source file's text, for positions.
#[derive(Debug)]
pub struct SourceFile {
    /// Path as displayed.
    pub name: String,
    /// Contents.
    pub text: String,
    /// The byte offset of each line's start, found on the first position asked.
    line_starts: std::sync::OnceLock<Vec<usize>>,
}

impl SourceFile {
    /// A file named `name` with contents `text`.
    ///
    /// ```
    /// use eulertop::claims::catalogue::SourceFile;
    /// let f = SourceFile::new("t.toml", "a = 1\nb = 2\n");
    /// assert_eq!(f.position(8), "t.toml:2");
    /// ```
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> SourceFile {
        SourceFile {
            name: name.into(),
            text: text.into(),
            line_starts: std::sync::OnceLock::new(),
        }
    }

    /// The 1-based line of byte `s` (a character boundary) and the offset of its start.
    fn line_of(&self, s: usize) -> (usize, usize) {
        let starts = self.line_starts.get_or_init(|| {
            std::iter::once(0)
                .chain(self.text.match_indices('\n').map(|(j, _)| j + 1))
                .collect()
        });
        // the lines starting at or before s; the first line starts at 0, so at least one
        let line = starts.partition_point(|&ls| ls <= s);
        (line, starts[line - 1])
    }

    /// An error at byte range `[start, end)` of the file.
    pub fn error_at(&self, start: usize, end: usize, message: impl Into<String>) -> LoadError {
        let s = self.text.floor_char_boundary(start);
        let (line, line_start) = self.line_of(s);
        let line_end = self.text[s..].find('\n').map_or(self.text.len(), |j| s + j);
        let col = self.text[line_start..s].chars().count() + 1;
        let e = self.text.floor_char_boundary(end.clamp(s, line_end.max(s)));
        LoadError {
            file: self.name.clone(),
            line,
            col,
            message: message.into(),
            line_text: self.text[line_start..line_end].to_string(),
            width: self.text[s..e].chars().count(),
        }
    }
    /// `file:line` of byte `at`.
    pub fn position(&self, at: usize) -> String {
        let s = self.text.floor_char_boundary(at);
        format!("{}:{}", self.name, self.line_of(s).0)
    }
}

/// The file text as UTF-8, or an error at the first invalid byte.
pub fn utf8(name: &str, bytes: Vec<u8>) -> Result<String, LoadError> {
    String::from_utf8(bytes).map_err(|e| {
        let bad = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let valid = String::from_utf8_lossy(&bytes[..bad]);
        let line_start = valid.rfind('\n').map_or(0, |j| j + 1);
        LoadError {
            file: name.to_string(),
            line: valid.matches('\n').count() + 1,
            col: valid[line_start..].chars().count() + 1,
            message: format!("not valid UTF-8 text (byte 0x{:02x})", bytes[bad]),
            line_text: String::new(),
            width: 0,
        }
    })
}

/// Where a string value sits in its file.
#[derive(Debug, Clone)]
pub struct Origin {
    /// The file.
    pub file: Arc<SourceFile>,
    /// Byte offset of the string's content in the file, when the content maps byte for
    /// byte (literal strings, or basic strings without escapes); else `None`.
    pub content_start: Option<usize>,
    /// The span of the whole TOML value (with quotes).
    pub value_span: (usize, usize),
}

impl Origin {
    /// The origin of a spanned string value of `file`.
    pub fn of(file: &Arc<SourceFile>, s: &Spanned<String>) -> Origin {
        let (a, b) = (s.span().start, s.span().end);
        let raw = file.text.get(a..b).unwrap_or("");
        let value = s.get_ref();
        let mut content_start = None;
        for (delim, literal) in [("'''", true), ("\"\"\"", false), ("'", true), ("\"", false)] {
            if raw.starts_with(delim) && raw.len() >= 2 * delim.len() {
                let mut c = a + delim.len();
                let mut inner = &raw[delim.len()..raw.len() - delim.len()];
                if delim.len() == 3 {
                    if let Some(rest) = inner.strip_prefix('\n') {
                        inner = rest;
                        c += 1;
                    } else if let Some(rest) = inner.strip_prefix("\r\n") {
                        inner = rest;
                        c += 2;
                    }
                }
                if inner == value && (literal || !inner.contains('\\')) {
                    content_start = Some(c);
                }
                break;
            }
        }
        Origin {
            file: file.clone(),
            content_start,
            value_span: (a, b),
        }
    }
    /// An error at a span of the string (the whole value when the span is unknown or the
    /// content does not map byte for byte).
    pub fn error(&self, span: Option<Span>, message: impl Into<String>) -> LoadError {
        match (self.content_start, span) {
            (Some(c), Some(sp)) => self.file.error_at(c + sp.start, c + sp.end, message),
            _ => self
                .file
                .error_at(self.value_span.0, self.value_span.1, message),
        }
    }
    /// `file:line` of the string.
    pub fn position(&self) -> String {
        self.file.position(self.value_span.0)
    }
}

/// A catalogue field value with its place in the file, for error messages.
#[derive(Debug, Clone)]
pub struct Located {
    /// The value as written.
    pub value: String,
    /// Where it is written.
    pub origin: Origin,
}

impl Located {
    /// A value read from the catalogue at `origin`.
    pub fn new(s: &Spanned<String>, origin: Origin) -> Located {
        Located {
            value: s.get_ref().clone(),
            origin,
        }
    }
    /// The spanned value `s` of `file`.
    pub fn of(file: &Arc<SourceFile>, s: &Spanned<String>) -> Located {
        Located::new(s, Origin::of(file, s))
    }
    /// An error pointing at the value.
    pub fn error(&self, message: impl Into<String>) -> LoadError {
        self.origin.error(None, message)
    }
}

/// The largest text file read whole: a catalogue file, a README, a LaTeX source (the
/// largest catalogue file is under 100 KB).
pub const MAX_TEXT_FILE_BYTES: u64 = 16 << 20;

/// The bytes of the regular file `path` (a symbolic link is followed), refused before
/// anything is read if it is not a regular file (a FIFO, a device, a directory) or is
/// larger than `limit` bytes; the message names the cause, not the file.
///
/// ```
/// use eulertop::claims::catalogue::source::read_regular;
/// let e = read_regular(std::path::Path::new("/dev/zero"), 1 << 20).unwrap_err();
/// assert!(e.contains("not a regular file"), "{e}");
/// ```
pub fn read_regular(path: &std::path::Path, limit: u64) -> Result<Vec<u8>, String> {
    use std::io::Read;
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot read: {e}"))?;
    let ft = meta.file_type();
    if !ft.is_file() {
        return Err(format!(
            "not a regular file ({}); only regular files are read",
            file_kind(&ft)
        ));
    }
    let too_big = |n: u64| {
        format!(
            "{n} bytes, above the limit of {} MiB for a text file",
            limit >> 20
        )
    };
    if meta.len() > limit {
        return Err(too_big(meta.len()));
    }
    let f = std::fs::File::open(path).map_err(|e| format!("cannot read: {e}"))?;
    let mut bytes = Vec::new();
    f.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read: {e}"))?;
    if bytes.len() as u64 > limit {
        // the file grew while it was read
        return Err(too_big(bytes.len() as u64));
    }
    Ok(bytes)
}

/// What a file that is not a regular file is, for the message.
fn file_kind(ft: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if ft.is_fifo() {
            return "a FIFO";
        }
        if ft.is_char_device() || ft.is_block_device() {
            return "a device";
        }
        if ft.is_socket() {
            return "a socket";
        }
    }
    if ft.is_dir() {
        "a directory"
    } else {
        "not a file"
    }
}

/// The text of a regular file of at most [`MAX_TEXT_FILE_BYTES`], as UTF-8.
///
/// ```
/// use eulertop::claims::catalogue::source::read_text;
/// let e = read_text(std::path::Path::new("/dev/zero")).unwrap_err();
/// assert!(e.contains("not a regular file"), "{e}");
/// ```
pub fn read_text(path: &std::path::Path) -> Result<String, String> {
    let bytes = read_regular(path, MAX_TEXT_FILE_BYTES)?;
    String::from_utf8(bytes)
        .map_err(|e| format!("not UTF-8 (byte {})", e.utf8_error().valid_up_to()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_without_position_are_one_line() {
        let e = LoadError::whole("dir", "cannot read");
        assert_eq!(e.to_string(), "dir: cannot read");
    }

    #[test]
    fn invalid_utf8_is_located() {
        let e = utf8("t.toml", b"a = 1\nb = \"\xff\"\n".to_vec()).unwrap_err();
        assert_eq!((e.line, e.col), (2, 6));
        assert_eq!(
            e.to_string(),
            "t.toml:2:6: not valid UTF-8 text (byte 0xff)"
        );
    }

    /// Lines and columns from the line index agree with counting from the start, at
    /// every character boundary (multi-byte characters, empty lines, a last line
    /// without its newline, the end of the text).
    #[test]
    fn the_line_index_agrees_with_counting() {
        let text = "a = 1\n\nβ = \"γδ\"\n  x\r\n é\nend";
        let f = SourceFile::new("f", text);
        for s in (0..=text.len()).filter(|&s| text.is_char_boundary(s)) {
            let line = text[..s].matches('\n').count() + 1;
            let line_start = text[..s].rfind('\n').map_or(0, |j| j + 1);
            let col = text[line_start..s].chars().count() + 1;
            let e = f.error_at(s, s, "");
            assert_eq!((e.line, e.col), (line, col), "byte {s}");
            assert_eq!(f.position(s), format!("f:{line}"), "byte {s}");
        }
        // past the end: the end of the text
        assert_eq!(f.position(text.len() + 5), format!("f:{}", 6));
    }

    #[test]
    fn positions_count_characters() {
        let f = SourceFile::new("f", "x = 1\ny = \"αβ\" + z\n");
        let at = f.text.find('z').unwrap();
        let e = f.error_at(at, at + 1, "unknown");
        assert_eq!((e.line, e.col, e.width), (2, 12, 1));
        assert!(
            e.to_string()
                .ends_with("\n    y = \"αβ\" + z\n               ^")
        );
    }
}
