//! libFuzzer target: arbitrary bytes through the lexer and the parser of the expression
//! language (as one expression and as a block of bindings).  Each must return a value or
//! a syntax error, never panic or overflow the stack.
#![no_main]

use eulertop::claims::lexer::lex;
use eulertop::claims::parser::{parse_bindings, parse_expr};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let src = String::from_utf8_lossy(data);
    let _ = lex(&src);
    let _ = parse_expr(&src);
    let _ = parse_bindings(&src);
});
