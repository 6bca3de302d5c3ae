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
                out.push(token(Tok::Newline, j, j + 1));
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
            let t = number(src, j)?;
            j = t.span.end;
            out.push(t);
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let s = j;
            while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'_') {
                j += 1;
            }
            out.push(token(Tok::Ident(src[s..j].to_string()), s, j));
        } else {
            let t = symbol(src, j)?;
            match t.tok {
                Tok::Sym("(" | "[") => depth += 1,
                Tok::Sym(")" | "]") => depth -= 1,
                _ => {}
            }
            j = t.span.end;
            out.push(t);
        }
    }
    Ok(out)
}

fn token(tok: Tok, start: usize, end: usize) -> Token {
    Token {
        tok,
        span: Span { start, end },
    }
}

/// A numeric literal starting at byte `s`: digits, at most one point, an optional
/// exponent; a letter right after it is an error (`2x`).
fn number(src: &str, s: usize) -> Result<Token, SyntaxError> {
    let b = src.as_bytes();
    let mut j = s;
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
        let word = &src[s..k];
        let hint = if b[j] == b'i' && k == j + 1 {
            format!(" (an imaginary number is written {}*i)", &src[s..j])
        } else {
            String::new()
        };
        return Err(SyntaxError {
            message: format!("malformed number '{word}'{hint}"),
            span: Span { start: s, end: k },
        });
    }
    Ok(token(Tok::Num(text.to_string()), s, j))
}

/// The operator or punctuation symbol at byte `j`.
fn symbol(src: &str, j: usize) -> Result<Token, SyntaxError> {
    let rest = &src[j..];
    match SYMS.iter().find(|s| rest.starts_with(**s)) {
        Some(sym) => Ok(token(Tok::Sym(sym), j, j + sym.len())),
        None => {
            let ch = rest.chars().next().unwrap_or('?');
            Err(SyntaxError {
                message: format!("unexpected character '{ch}'"),
                span: Span {
                    start: j,
                    end: j + ch.len_utf8(),
                },
            })
        }
    }
}
