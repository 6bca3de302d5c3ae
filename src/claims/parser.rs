//! Recursive-descent parser of the expression language (grammar in
//! `identities/README.md`).  Never panics: every malformed input is a [`SyntaxError`]
//! with the byte span of the offending text.

use super::ast::{BinOp, Binding, Expr, ExprKind, Span, UnOp};
use super::lexer::{SyntaxError, Tok, Token, lex};

const KEYWORDS: [&str; 6] = ["if", "then", "else", "and", "or", "not"];
/// Most nested brackets, calls and prefix operators (bounds the parser's recursion).
const MAX_DEPTH: usize = 200;
/// Most levels of the syntax tree, long flat chains such as `1 + 1 + … + 1` included
/// (bounds the recursion of everything that walks the tree: evaluation, LaTeX, …).
pub const MAX_HEIGHT: usize = 256;

struct Parser<'a> {
    toks: Vec<Token>,
    pos: usize,
    src: &'a str,
    depth: usize,
    /// The height of the expression the last parse function returned.
    height: usize,
}

/// Parses one expression (the whole string).
pub fn parse_expr(src: &str) -> Result<Expr, SyntaxError> {
    let mut p = Parser::new(src)?;
    p.skip_newlines();
    let e = p.expr()?;
    p.skip_newlines();
    p.expect_end()?;
    Ok(e)
}

/// Parses a block of bindings, one per line: `name = expr` or `name(p, ...) = expr`.
pub fn parse_bindings(src: &str) -> Result<Vec<Binding>, SyntaxError> {
    let mut p = Parser::new(src)?;
    let mut out = Vec::new();
    loop {
        p.skip_newlines();
        if p.pos >= p.toks.len() {
            break;
        }
        out.push(p.binding()?);
        match p.peek() {
            None | Some(Tok::Newline) | Some(Tok::Sym(";")) => {
                p.pos += 1;
            }
            Some(_) => return Err(p.err_here("expected end of line after binding")),
        }
    }
    Ok(out)
}

impl<'a> Parser<'a> {
    fn new(src: &'a str) -> Result<Self, SyntaxError> {
        Ok(Parser {
            toks: lex(src)?,
            pos: 0,
            src,
            depth: 0,
            height: 0,
        })
    }
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|t| &t.tok)
    }
    fn span_here(&self) -> Span {
        match self.toks.get(self.pos) {
            Some(t) => t.span,
            None => Span {
                start: self.src.len(),
                end: self.src.len(),
            },
        }
    }
    fn err_here(&self, msg: &str) -> SyntaxError {
        let found = match self.toks.get(self.pos) {
            None => "end of input".to_string(),
            Some(t) => match &t.tok {
                Tok::Newline => "end of line".to_string(),
                _ => format!("'{}'", &self.src[t.span.start..t.span.end]),
            },
        };
        SyntaxError {
            message: format!("{msg}, found {found}"),
            span: self.span_here(),
        }
    }
    fn skip_newlines(&mut self) {
        while matches!(self.peek(), Some(Tok::Newline)) {
            self.pos += 1;
        }
    }
    fn expect_end(&self) -> Result<(), SyntaxError> {
        if self.pos < self.toks.len() {
            Err(self.err_here("expected end of expression"))
        } else {
            Ok(())
        }
    }
    fn is_sym(&self, s: &str) -> bool {
        matches!(self.peek(), Some(Tok::Sym(x)) if *x == s)
    }
    fn is_kw(&self, s: &str) -> bool {
        matches!(self.peek(), Some(Tok::Ident(x)) if x == s)
    }
    fn eat_sym(&mut self, s: &str) -> Result<Span, SyntaxError> {
        if self.is_sym(s) {
            self.pos += 1;
            Ok(self.toks[self.pos - 1].span)
        } else {
            Err(self.err_here(&format!("expected '{s}'")))
        }
    }
    fn eat_kw(&mut self, s: &str) -> Result<(), SyntaxError> {
        if self.is_kw(s) {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.err_here(&format!("expected '{s}'")))
        }
    }
    fn name(&mut self) -> Result<(String, Span), SyntaxError> {
        match self.toks.get(self.pos) {
            Some(Token {
                tok: Tok::Ident(n),
                span,
            }) if !KEYWORDS.contains(&n.as_str()) => {
                let r = (n.clone(), *span);
                self.pos += 1;
                Ok(r)
            }
            _ => Err(self.err_here("expected a name")),
        }
    }

    fn binding(&mut self) -> Result<Binding, SyntaxError> {
        let (name, span) = self.name()?;
        let params = if self.is_sym("(") {
            self.pos += 1;
            let mut ps = Vec::new();
            if !self.is_sym(")") {
                loop {
                    let (p, at) = self.name()?;
                    if ps.contains(&p) {
                        return Err(SyntaxError {
                            message: format!("duplicate parameter '{p}' of '{name}'"),
                            span: at,
                        });
                    }
                    ps.push(p);
                    if self.is_sym(",") {
                        self.pos += 1;
                    } else {
                        break;
                    }
                }
            }
            self.eat_sym(")")?;
            Some(ps)
        } else {
            None
        };
        self.eat_sym("=")?;
        let body = self.expr()?;
        Ok(Binding {
            name,
            params,
            body,
            span,
        })
    }

    fn enter(&mut self) -> Result<(), SyntaxError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(SyntaxError {
                message: format!(
                    "expression nested too deeply (more than {MAX_DEPTH} levels: a parenthesis, unary sign, 'not' or exponent counts one, a call or bracket two)"
                ),
                span: self.span_here(),
            });
        }
        Ok(())
    }

    /// Records a new node over children of heights `hs` (at the current position).
    fn node(&mut self, hs: &[usize]) -> Result<(), SyntaxError> {
        let h = 1 + hs.iter().copied().max().unwrap_or(0);
        if h > MAX_HEIGHT {
            return Err(SyntaxError {
                message: format!(
                    "expression nested too deeply (more than {MAX_HEIGHT} levels; a chain of operators counts one level per operator)"
                ),
                span: self.span_here(),
            });
        }
        self.height = h;
        Ok(())
    }

    fn expr(&mut self) -> Result<Expr, SyntaxError> {
        self.enter()?;
        let r = if self.is_kw("if") {
            let s = self.span_here();
            self.pos += 1;
            let c = self.expr()?;
            let hc = self.height;
            self.eat_kw("then")?;
            let a = self.expr()?;
            let ha = self.height;
            self.eat_kw("else")?;
            let b = self.expr()?;
            let hb = self.height;
            self.node(&[hc, ha, hb])?;
            let span = s.join(b.span);
            Ok(Expr {
                kind: ExprKind::If(Box::new(c), Box::new(a), Box::new(b)),
                span,
            })
        } else {
            self.or()
        };
        self.depth -= 1;
        r
    }

    fn bin(op: BinOp, a: Expr, b: Expr) -> Expr {
        let span = a.span.join(b.span);
        Expr {
            kind: ExprKind::Binary(op, Box::new(a), Box::new(b)),
            span,
        }
    }

    fn or(&mut self) -> Result<Expr, SyntaxError> {
        let mut a = self.and()?;
        while self.is_kw("or") {
            let ha = self.height;
            self.pos += 1;
            let b = self.and()?;
            self.node(&[ha, self.height])?;
            a = Self::bin(BinOp::Or, a, b);
        }
        Ok(a)
    }
    fn and(&mut self) -> Result<Expr, SyntaxError> {
        let mut a = self.not()?;
        while self.is_kw("and") {
            let ha = self.height;
            self.pos += 1;
            let b = self.not()?;
            self.node(&[ha, self.height])?;
            a = Self::bin(BinOp::And, a, b);
        }
        Ok(a)
    }
    fn not(&mut self) -> Result<Expr, SyntaxError> {
        if self.is_kw("not") {
            let s = self.span_here();
            self.pos += 1;
            self.enter()?;
            let a = self.not()?;
            self.depth -= 1;
            self.node(&[self.height])?;
            let span = s.join(a.span);
            return Ok(Expr {
                kind: ExprKind::Unary(UnOp::Not, Box::new(a)),
                span,
            });
        }
        self.cmp()
    }
    fn cmp(&mut self) -> Result<Expr, SyntaxError> {
        let a = self.sum()?;
        let op = match self.peek() {
            Some(Tok::Sym("<")) => BinOp::Lt,
            Some(Tok::Sym(">")) => BinOp::Gt,
            Some(Tok::Sym("<=")) => BinOp::Le,
            Some(Tok::Sym(">=")) => BinOp::Ge,
            Some(Tok::Sym("==")) => BinOp::Eq,
            Some(Tok::Sym("!=")) => BinOp::Ne,
            _ => return Ok(a),
        };
        let ha = self.height;
        self.pos += 1;
        let b = self.sum()?;
        self.node(&[ha, self.height])?;
        Ok(Self::bin(op, a, b))
    }
    fn sum(&mut self) -> Result<Expr, SyntaxError> {
        let mut a = self.term()?;
        loop {
            let op = match self.peek() {
                Some(Tok::Sym("+")) => BinOp::Add,
                Some(Tok::Sym("-")) => BinOp::Sub,
                _ => return Ok(a),
            };
            let ha = self.height;
            self.pos += 1;
            let b = self.term()?;
            self.node(&[ha, self.height])?;
            a = Self::bin(op, a, b);
        }
    }
    fn term(&mut self) -> Result<Expr, SyntaxError> {
        let mut a = self.unary()?;
        loop {
            let op = match self.peek() {
                Some(Tok::Sym("*")) => BinOp::Mul,
                Some(Tok::Sym("/")) => BinOp::Div,
                _ => return Ok(a),
            };
            let ha = self.height;
            self.pos += 1;
            let b = self.unary()?;
            self.node(&[ha, self.height])?;
            a = Self::bin(op, a, b);
        }
    }
    fn unary(&mut self) -> Result<Expr, SyntaxError> {
        if self.is_sym("-") || self.is_sym("+") {
            let neg = self.is_sym("-");
            let s = self.span_here();
            self.pos += 1;
            self.enter()?;
            let a = self.unary()?;
            self.depth -= 1;
            if !neg {
                return Ok(a);
            }
            self.node(&[self.height])?;
            let span = s.join(a.span);
            return Ok(Expr {
                kind: ExprKind::Unary(UnOp::Neg, Box::new(a)),
                span,
            });
        }
        self.power()
    }
    fn power(&mut self) -> Result<Expr, SyntaxError> {
        let a = self.postfix()?;
        if self.is_sym("^") {
            let ha = self.height;
            self.pos += 1;
            self.enter()?;
            let b = self.unary()?;
            self.depth -= 1;
            self.node(&[ha, self.height])?;
            return Ok(Self::bin(BinOp::Pow, a, b));
        }
        Ok(a)
    }
    fn postfix(&mut self) -> Result<Expr, SyntaxError> {
        let mut a = self.primary()?;
        while self.is_sym("[") {
            let mut hs = vec![self.height];
            self.pos += 1;
            let mut ix = vec![self.expr()?];
            hs.push(self.height);
            if self.is_sym(",") {
                self.pos += 1;
                ix.push(self.expr()?);
                hs.push(self.height);
            }
            let e = self.eat_sym("]")?;
            self.node(&hs)?;
            let span = a.span.join(e);
            a = Expr {
                kind: ExprKind::Index(Box::new(a), ix),
                span,
            };
        }
        Ok(a)
    }
    /// A comma-separated list up to `close`; leaves the largest height of the items.
    fn args(&mut self, close: &str) -> Result<(Vec<Expr>, Span), SyntaxError> {
        let mut v = Vec::new();
        let mut h = 0;
        if !self.is_sym(close) {
            loop {
                v.push(self.expr()?);
                h = h.max(self.height);
                if self.is_sym(",") {
                    self.pos += 1;
                } else {
                    break;
                }
            }
        }
        let e = self.eat_sym(close)?;
        self.height = h;
        Ok((v, e))
    }
    fn primary(&mut self) -> Result<Expr, SyntaxError> {
        let Some(t) = self.toks.get(self.pos).cloned() else {
            return Err(self.err_here("expected an expression"));
        };
        match t.tok {
            Tok::Num(s) => {
                self.pos += 1;
                self.height = 1;
                Ok(Expr {
                    kind: ExprKind::Num(s),
                    span: t.span,
                })
            }
            Tok::Sym("(") => {
                // one level: that of the expression inside; the span covers the
                // parentheses, so an excerpt of `(1+x)^n` keeps its `(`
                self.pos += 1;
                let e = self.expr()?;
                let close = self.eat_sym(")")?;
                Ok(Expr {
                    span: t.span.join(close),
                    ..e
                })
            }
            Tok::Sym("[") => {
                self.pos += 1;
                self.enter()?;
                let (items, e) = self.args("]")?;
                self.depth -= 1;
                self.node(&[self.height])?;
                Ok(Expr {
                    kind: ExprKind::List(items),
                    span: t.span.join(e),
                })
            }
            Tok::Ident(ref n) if !KEYWORDS.contains(&n.as_str()) => {
                self.pos += 1;
                if !self.is_sym("(") {
                    self.height = 1;
                    return Ok(Expr {
                        kind: ExprKind::Name(n.clone()),
                        span: t.span,
                    });
                }
                self.pos += 1;
                self.enter()?;
                let (args, e) = self.args(")")?;
                self.depth -= 1;
                self.node(&[self.height])?;
                let span = t.span.join(e);
                special_form(n, args, span)
            }
            _ => Err(self.err_here("expected an expression")),
        }
    }
}

fn binder(e: &Expr, what: &str) -> Result<String, SyntaxError> {
    match &e.kind {
        ExprKind::Name(n) if n != "pi" && n != "i" => Ok(n.clone()),
        ExprKind::Name(n) => Err(SyntaxError {
            message: format!(
                "{what} must be a variable name, and '{n}' is the constant {}",
                if n == "i" {
                    "i, the imaginary unit"
                } else {
                    "pi"
                }
            ),
            span: e.span,
        }),
        _ => Err(SyntaxError {
            message: format!("{what} must be a variable name"),
            span: e.span,
        }),
    }
}

/// Turns the binder calls `sum`, `prod`, `d` and `grad` into their special forms.
fn special_form(name: &str, mut args: Vec<Expr>, span: Span) -> Result<Expr, SyntaxError> {
    let nargs = args.len();
    let arity_err = |want: &str| SyntaxError {
        message: format!("{name} takes {want} arguments, got {nargs}"),
        span,
    };
    let kind = match name {
        "sum" | "prod" => {
            if args.len() != 4 {
                return Err(arity_err("4"));
            }
            let body = args.pop().map(Box::new);
            let to = args.pop().map(Box::new);
            let from = args.pop().map(Box::new);
            let var = binder(&args[0], "the loop variable")?;
            match (body, to, from) {
                (Some(body), Some(to), Some(from)) => ExprKind::Sum {
                    var,
                    from,
                    to,
                    body,
                    product: name == "prod",
                },
                _ => return Err(arity_err("4")),
            }
        }
        "d" => {
            if args.len() != 2 && args.len() != 3 {
                return Err(arity_err("2 or 3"));
            }
            let var = binder(&args[1], "the differentiation variable")?;
            let component = if args.len() == 3 {
                args.pop().map(Box::new)
            } else {
                None
            };
            let body = Box::new(args.swap_remove(0));
            ExprKind::Deriv {
                body,
                var,
                component,
            }
        }
        "grad" => {
            if args.len() != 2 {
                return Err(arity_err("2"));
            }
            let var = binder(&args[1], "the differentiation variable")?;
            let body = Box::new(args.swap_remove(0));
            ExprKind::Grad { body, var }
        }
        _ => ExprKind::Call(name.to_string(), args),
    };
    Ok(Expr { kind, span })
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn precedence() {
        let e = parse_expr("-x^2 + 2*y").unwrap();
        match e.kind {
            ExprKind::Binary(BinOp::Add, a, _) => {
                assert!(matches!(a.kind, ExprKind::Unary(UnOp::Neg, _)))
            }
            _ => panic!("bad parse"),
        }
        assert!(parse_expr("2^-1").is_ok());
        assert!(parse_expr("if a < b then 1 else 2").is_ok());
    }
    #[test]
    fn errors_have_spans() {
        let e = parse_expr("1 + * 2").unwrap_err();
        assert_eq!(e.span.start, 4);
        let e = parse_expr("sin(x").unwrap_err();
        assert_eq!(e.span.start, 5);
        assert!(parse_bindings("a = 1\nb(x) = x^2\n").unwrap().len() == 2);
        assert!(parse_bindings("a = 1 2").is_err());
    }
}
