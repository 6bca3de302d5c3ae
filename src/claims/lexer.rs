//! Tokenizer of the expression language.  Newlines are tokens only outside brackets
//! (they separate bindings of a `let` block); `#` starts a comment to the end of the line.

use super::ast::Span;

/// A token kind.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// A numeric literal as written.
    Num(String),
    /// A name (or keyword).
    Ident(String),
    /// A punctuation or operator symbol.
    Sym(&'static str),
    /// A line break outside brackets.
    Newline,
}

/// A token with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    /// The token.
    pub tok: Tok,
    /// Where it is.
    pub span: Span,
}

/// A lexical or syntax error at a byte range of the source.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct SyntaxError {
    /// What is wrong.
    pub message: String,
    /// Where.
    pub span: Span,
}

const SYMS: [&str; 19] = [
    "<=", ">=", "==", "!=", "+", "-", "*", "/", "^", "(", ")", "[", "]", ",", "<", ">", "=", ";",
    "'",
];

/// Splits `src` into tokens.
pub fn lex(src: &str) -> Result<Vec<Token>, SyntaxError> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut depth: i64 = 0;
    let mut j = 0;
    while j < b.len() {
        let c = b[j];
        if c == b'\n' {
            if depth <= 0 {
                out.push(Token {
                    tok: Tok::Newline,
                    span: Span {
                        start: j,
                        end: j + 1,
                    },
                });
            }
            j += 1;
        } else if c.is_ascii_whitespace() {
            j += 1;
        } else if c == b'#' {
            while j < b.len() && b[j] != b'\n' {
                j += 1;
            }
        } else if c.is_ascii_digit() || (c == b'.' && j + 1 < b.len() && b[j + 1].is_ascii_digit())
        {
            let s = j;
            while j < b.len() && (b[j].is_ascii_digit() || b[j] == b'.') {
                j += 1;
            }
            if j < b.len() && (b[j] == b'e' || b[j] == b'E') {
                let mut k = j + 1;
                if k < b.len() && (b[k] == b'+' || b[k] == b'-') {
                    k += 1;
                }
                if k < b.len() && b[k].is_ascii_digit() {
                    j = k;
                    while j < b.len() && b[j].is_ascii_digit() {
                        j += 1;
                    }
                }
            }
            let text = &src[s..j];
            if text.matches('.').count() > 1 {
                return Err(SyntaxError {
                    message: format!("malformed number '{text}'"),
                    span: Span { start: s, end: j },
                });
            }
            if j < b.len() && (b[j].is_ascii_alphabetic() || b[j] == b'_') {
                let mut k = j;
                while k < b.len() && (b[k].is_ascii_alphanumeric() || b[k] == b'_') {
                    k += 1;
                }
                return Err(SyntaxError {
                    message: format!("malformed number '{}'", &src[s..k]),
                    span: Span { start: s, end: k },
                });
            }
            out.push(Token {
                tok: Tok::Num(text.to_string()),
                span: Span { start: s, end: j },
            });
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let s = j;
            while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'_') {
                j += 1;
            }
            out.push(Token {
                tok: Tok::Ident(src[s..j].to_string()),
                span: Span { start: s, end: j },
            });
        } else {
            let rest = &src[j..];
            let Some(sym) = SYMS.iter().find(|s| rest.starts_with(**s)) else {
                let ch = rest.chars().next().unwrap_or('?');
                return Err(SyntaxError {
                    message: format!("unexpected character '{ch}'"),
                    span: Span {
                        start: j,
                        end: j + ch.len_utf8(),
                    },
                });
            };
            match *sym {
                "(" | "[" => depth += 1,
                ")" | "]" => depth -= 1,
                _ => {}
            }
            out.push(Token {
                tok: Tok::Sym(sym),
                span: Span {
                    start: j,
                    end: j + sym.len(),
                },
            });
            j += sym.len();
        }
    }
    Ok(out)
}
