//! Rendering: literals, identifiers and polynomials as tokens (for code) and as text (for the
//! symbolic expansions in doc comments).

use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Monomial, Poly, Var};
use crate::runtime::rational::Rational;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::cell::Cell;
use std::fmt::Write;

/// An identifier (names are checked once, up front, by [`super::check_names`]).
pub(super) fn ident(name: &str) -> Ident {
    Ident::new(name, Span::call_site())
}

/// True for a name that can be a Rust identifier in generated code: an identifier for syn
/// (Unicode letters allowed), not a raw identifier, and not a keyword of any edition.
pub(super) fn is_ident(name: &str) -> bool {
    const KEYWORDS: &[&str] = &[
        "_", "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum",
        "extern", "false", "fn", "for", "if", "impl", "in", "let", "loop", "match", "mod", "move",
        "mut", "pub", "ref", "return", "self", "Self", "static", "struct", "super", "trait",
        "true", "type", "unsafe", "use", "where", "while", "abstract", "become", "box", "do",
        "final", "gen", "macro", "override", "priv", "try", "typeof", "unsized", "virtual",
        "yield",
    ];
    !name.contains('#') && !KEYWORDS.contains(&name) && syn::parse_str::<Ident>(name).is_ok()
}

/// An unsuffixed integer literal.
pub(super) fn int(n: usize) -> Literal {
    Literal::usize_unsuffixed(n)
}

/// The text of a float literal: Rust's shortest round-trip form, with `.0` added to integers.
pub(super) fn float_text(x: f64) -> String {
    let s = format!("{x:?}");
    if s.contains('.') || s.contains('e') {
        s
    } else {
        format!("{s}.0")
    }
}

/// A float constant as tokens (`-` then the magnitude for negative values).
pub(super) fn float(x: f64) -> TokenStream {
    let text = float_text(x.abs());
    let mag = match text.parse::<Literal>() {
        Ok(l) => quote!(#l),
        // Not finite (`inf`, `NaN`): written as the text would read.
        Err(_) => {
            let id = ident(&text);
            quote!(#id)
        }
    };
    if x < 0.0 {
        quote!(- #mag)
    } else {
        mag
    }
}

/// An exact coefficient as a float constant.
pub(super) fn lit(c: Rational) -> TokenStream {
    float(c.to_f64())
}

/// snake_case of an UpperCamel name.
pub fn snake(name: &str) -> String {
    let mut s = String::new();
    for (i, ch) in name.chars().enumerate() {
        if ch.is_ascii_uppercase() {
            if i > 0 {
                s.push('_');
            }
            s.push(ch.to_ascii_lowercase());
        } else {
            s.push(ch);
        }
    }
    s
}

/// Renders polynomials with variable names: operand 0 is `a.field`, operand 1 `b.field`,
/// operand 3 the factor `r`, any other operand the scalar `s`.
pub(super) struct Names<'a> {
    types: [Option<&'a TypeDef>; 2],
    /// Set when a rendered expression reads operand 0 (`a`).
    reads_a: Cell<bool>,
}

impl<'a> Names<'a> {
    /// Names for a unary (`b` absent) or binary expression.
    pub(super) fn new(a: &'a TypeDef, b: Option<&'a TypeDef>) -> Names<'a> {
        Names {
            types: [Some(a), b],
            reads_a: Cell::new(false),
        }
    }

    /// Whether anything rendered so far reads `a`.
    pub(super) fn reads_a(&self) -> bool {
        self.reads_a.get()
    }

    fn field(&self, v: Var) -> Option<(&'static str, &str)> {
        match v.operand {
            0 | 1 => {
                let t = self.types[v.operand as usize].expect("operand type");
                let prefix = if v.operand == 0 { "a" } else { "b" };
                Some((prefix, t.fields[v.field as usize].name.as_str()))
            }
            _ => None,
        }
    }

    pub(super) fn var(&self, v: Var) -> TokenStream {
        match self.field(v) {
            Some((prefix, f)) => {
                if v.operand == 0 {
                    self.reads_a.set(true);
                }
                let (p, f) = (ident(prefix), ident(f));
                quote!(#p.#f)
            }
            None if v.operand == 3 => quote!(r),
            None => quote!(s),
        }
    }

    /// `x * y * z`.
    pub(super) fn monomial(&self, m: &Monomial) -> TokenStream {
        let mut out = TokenStream::new();
        for (i, v) in m.iter().enumerate() {
            if i > 0 {
                out.extend(quote!(*));
            }
            out.extend(self.var(*v));
        }
        out
    }

    /// `c1 * m1 + c2 * m2 - ...`, or `0.0`.
    pub(super) fn poly(&self, p: &Poly) -> TokenStream {
        self.poly_with(p, |m| self.monomial(m))
    }

    /// [`Names::poly`] with monomials rendered by `mono` (shared subexpressions).
    pub(super) fn poly_with(
        &self,
        p: &Poly,
        mono: impl Fn(&Monomial) -> TokenStream,
    ) -> TokenStream {
        poly_tokens(p, mono)
    }

    /// The text of `x * y * z`, for docs.
    pub(super) fn monomial_text(&self, m: &Monomial) -> String {
        m.iter()
            .map(|v| match self.field(*v) {
                Some((p, f)) => format!("{p}.{f}"),
                None if v.operand == 3 => "r".to_string(),
                None => "s".to_string(),
            })
            .collect::<Vec<_>>()
            .join(" * ")
    }

    /// The text of [`Names::poly`], for docs.
    pub(super) fn poly_text(&self, p: &Poly) -> String {
        if p.is_zero() {
            return "0.0".to_string();
        }
        let mut s = String::new();
        for (i, (m, &c)) in p.0.iter().enumerate() {
            let neg = c < Rational::ZERO;
            let mag = if neg { -c } else { c };
            if i == 0 {
                if neg {
                    s.push('-');
                }
            } else {
                s.push_str(if neg { " - " } else { " + " });
            }
            if m.is_empty() {
                s.push_str(&float_text(mag.to_f64()));
            } else if mag == Rational::ONE {
                s.push_str(&self.monomial_text(m));
            } else {
                let _ = write!(
                    s,
                    "{} * {}",
                    float_text(mag.to_f64()),
                    self.monomial_text(m)
                );
            }
        }
        s
    }
}

/// A doc text as one `#[doc = " line"]` per line, each starting with a space as `///` comments
/// do, so that the formatted code reads `/// line` (never `///line` or `/** .. */`).
/// Lines end at `\n` or `\r\n` (a spec written on Windows); any other control character is
/// written escaped (a bare `\r` is an error in a Rust doc comment).
pub(super) fn doc(text: &str) -> TokenStream {
    let lines = text.lines().map(|l| {
        if l.is_empty() {
            String::new()
        } else {
            format!(" {}", one_line(l))
        }
    });
    quote!(#(#[doc = #lines])*)
}

/// `text` with its control characters (line breaks included) escaped as `\n`, `\r`,
/// `\u{..}`, so that it stays on the comment line it is written in (a spec's name, path or
/// doc line).
pub(super) fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() && c != '\t' {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// `c1 * m1 + c2 * m2 - ...` with monomials rendered by `mono`, or `0.0`: every emitted
/// polynomial goes through here.
pub(super) fn poly_tokens(p: &Poly, mono: impl Fn(&Monomial) -> TokenStream) -> TokenStream {
    if p.is_zero() {
        return quote!(0.0);
    }
    let mut s = TokenStream::new();
    for (i, (m, &c)) in p.0.iter().enumerate() {
        let neg = c < Rational::ZERO;
        let mag = if neg { -c } else { c };
        if neg {
            s.extend(quote!(-));
        } else if i > 0 {
            s.extend(quote!(+));
        }
        if m.is_empty() {
            s.extend(lit(mag));
        } else if mag == Rational::ONE {
            s.extend(mono(m));
        } else {
            s.extend(lit(mag));
            s.extend(quote!(*));
            s.extend(mono(m));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::is_ident;

    #[test]
    fn identifiers() {
        for ok in ["e1", "eo12i", "s", "Motor", "e_x", "eα"] {
            assert!(is_ident(ok), "{ok}");
        }
        for bad in [
            "", "1e", "e-1", "e 1", "enum", "self", "Self", "_", "r#e1", "gen", "e1.0",
        ] {
            assert!(!is_ident(bad), "{bad}");
        }
    }
}
