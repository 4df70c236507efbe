//! The token grammar of `algebra!`: parsed with syn into a [`RawSpec`] plus the source range
//! of every name and number, so that spec errors can point at the token they concern.

use ga_codegen::generator::spec::{RawSandwich, RawSpec, RawType};
use ga_codegen::ScalarType;
use proc_macro2::{Punct, Spacing, Span, TokenStream, TokenTree};
use quote::ToTokens;
use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::{braced, bracketed, parenthesized, Attribute, Ident, Lit, LitStr, Token};

/// A source range: the first and the last token of something.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Range {
    /// Span of the first token.
    pub start: Span,
    /// Span of the last token.
    pub end: Span,
}

impl Range {
    /// A range of one token (or one delimited group).
    pub fn one(span: Span) -> Range {
        Range {
            start: span,
            end: span,
        }
    }

    /// From the start of `self` to the end of `other`.
    fn to(self, other: Range) -> Range {
        Range {
            start: self.start,
            end: other.end,
        }
    }

    /// The whole macro invocation.
    pub fn call_site() -> Range {
        Range::one(Span::call_site())
    }
}

/// `syn::Error::new_spanned` underlines from the first to the last token it is given, which
/// is how a stable proc-macro reports an error over a range.
impl ToTokens for Range {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        for span in [self.start, self.end] {
            let mut p = Punct::new('.', Spacing::Alone);
            p.set_span(span);
            tokens.extend([TokenTree::Punct(p)]);
        }
    }
}

/// An error over a range.
pub(crate) fn error_at(range: Range, message: impl std::fmt::Display) -> syn::Error {
    syn::Error::new_spanned(range, message)
}

/// The macro input.
pub(crate) struct Input {
    /// Where the spec comes from.
    pub source: Source,
    /// `scalar = f32 | f64` (default f64).
    pub scalar: ScalarType,
    /// `runtime = path` (default `::ga_codegen`).
    pub runtime: Option<String>,
    /// `exp_log = required`: a type without closed-form exp/log is an error.
    pub require_exp_log: bool,
}

/// Where the spec comes from.
pub(crate) enum Source {
    /// `path = "file.toml"`.
    File(LitStr),
    /// The spec written inline.
    Inline(Box<Inline>),
}

/// An inline spec: the raw spec and where each part of it was written.
pub(crate) struct Inline {
    /// The spec as written.
    pub raw: RawSpec,
    /// Where its parts were written.
    pub spans: Spans,
}

/// Source ranges of the parts of an inline spec (parallel to the [`RawSpec`] fields).
#[derive(Default)]
pub(crate) struct Spans {
    /// The `[...]` of `basis`.
    pub basis_list: Option<Range>,
    /// Each basis name.
    pub basis: Vec<Range>,
    /// `metric = [[..], ..]`.
    pub metric: Option<Matrix>,
    /// `diagonal = [..]`.
    pub diagonal: Option<List>,
    /// Each `type`, in order.
    pub types: Vec<TypeSpans>,
    /// Each `sandwich`, in order.
    pub sandwiches: Vec<SandwichSpans>,
}

/// Ranges of a matrix of numbers.
pub(crate) struct Matrix {
    /// The outer brackets.
    pub whole: Range,
    /// Each row's brackets.
    pub rows: Vec<Range>,
    /// Each entry.
    pub entries: Vec<Vec<Range>>,
}

/// Ranges of a list of numbers.
pub(crate) struct List {
    /// The brackets.
    pub whole: Range,
    /// Each entry.
    pub entries: Vec<Range>,
}

/// Ranges of a `type` item.
pub(crate) struct TypeSpans {
    /// The type name.
    pub name: Range,
    /// Each blade name in `blades = [...]`.
    pub blades: Vec<Range>,
    /// Each constant: blade name, its range, and the range of its value.
    pub constants: Vec<(String, Range, Range)>,
}

/// Ranges of a `sandwich` item.
pub(crate) struct SandwichSpans {
    /// From `sandwich` to the last type name.
    pub whole: Range,
    /// The versor type name.
    pub versor: Range,
    /// The operand type name.
    pub operand: Range,
    /// The output type name.
    pub output: Option<Range>,
}

const EXPECTED_ITEM: &str = "expected `key = value;`, `type Name { .. }` or \
     `sandwich Versor(Operand) -> Output;` (keys: name, doc, basis, metric, diagonal, scalar, \
     runtime, exp_log, path)";

/// Top-level keys that give (part of) the spec, which `path = ...` excludes.
const SPEC_KEYS: [&str; 5] = ["name", "doc", "basis", "metric", "diagonal"];

impl Parse for Input {
    fn parse(input: ParseStream) -> syn::Result<Input> {
        let mut p = Parsed::default();
        // `//! ...` at the start: the algebra's documentation.
        let inner = input.call(Attribute::parse_inner)?;
        if let Some((doc, range)) = doc_of(&inner)? {
            p.raw.doc = Some(doc);
            p.seen.push(("doc".to_string(), range));
        }
        while !input.is_empty() {
            let attrs = input.call(Attribute::parse_outer)?;
            let doc = doc_of(&attrs)?;
            if input.peek(Token![type]) {
                let (t, s) = parse_type(input, doc.map(|d| d.0))?;
                p.items.get_or_insert(s.name);
                p.raw.types.push(t);
                p.spans.types.push(s);
                if input.peek(Token![;]) {
                    input.parse::<Token![;]>()?;
                } else if input.peek(Token![,]) {
                    input.parse::<Token![,]>()?;
                }
                continue;
            }
            if let Some((_, range)) = doc {
                return Err(error_at(
                    range,
                    "doc comments go on `type` items only; document the algebra with \
                     `//! ...` at the start or `doc = \"...\";`",
                ));
            }
            if !input.peek(Ident::peek_any) {
                return Err(input.error(EXPECTED_ITEM));
            }
            let key = input.call(Ident::parse_any)?;
            let key_range = Range::one(key.span());
            if key.unraw() == "sandwich" {
                let (s, r) = parse_sandwich(input, key_range)?;
                p.items.get_or_insert(r.whole);
                p.raw.sandwich.push(s);
                p.spans.sandwiches.push(r);
            } else {
                p.key_value(input, &key)?;
            }
            if input.is_empty() {
                break;
            }
            if input.peek(Token![;]) {
                input.parse::<Token![;]>()?;
            } else if input.peek(Token![,]) {
                input.parse::<Token![,]>()?;
            } else {
                return Err(input.error("expected `;`"));
            }
        }
        p.finish()
    }
}

/// What the macro's input has given so far.
#[derive(Default)]
struct Parsed {
    raw: RawSpec,
    spans: Spans,
    scalar: Option<ScalarType>,
    runtime: Option<String>,
    require_exp_log: bool,
    path: Option<LitStr>,
    /// Keys seen, with the range of the key, for "given twice" and "not with `path`".
    seen: Vec<(String, Range)>,
    /// The first `type` or `sandwich` item.
    items: Option<Range>,
}

impl Parsed {
    /// `key = value`: refused when given twice, or beside the other of `metric` and
    /// `diagonal`.
    fn key_value(&mut self, input: ParseStream, key: &Ident) -> syn::Result<()> {
        let key_range = Range::one(key.span());
        let k = key.unraw().to_string();
        if let Some((_, first)) = self.seen.iter().find(|(s, _)| *s == k) {
            let mut e = error_at(key_range, format!("`{k}` given twice"));
            e.combine(error_at(*first, format!("`{k}` first given here")));
            return Err(e);
        }
        let other = match k.as_str() {
            "metric" => Some("diagonal"),
            "diagonal" => Some("metric"),
            _ => None,
        };
        if let Some((o, first)) = self.seen.iter().find(|(s, _)| Some(s.as_str()) == other) {
            let mut e = error_at(
                key_range,
                "give only one of `metric` (the full matrix) and `diagonal` (the squares)",
            );
            e.combine(error_at(*first, format!("`{o}` given here")));
            return Err(e);
        }
        input.parse::<Token![=]>()?;
        let (raw, spans) = (&mut self.raw, &mut self.spans);
        match k.as_str() {
            "name" => raw.name = Some(input.parse::<LitStr>()?.value()),
            "doc" => raw.doc = Some(input.parse::<LitStr>()?.value()),
            "basis" => {
                let (names, whole) = parse_list(input, parse_name)?;
                spans.basis_list = Some(whole);
                for (n, r) in names {
                    raw.basis.push(n);
                    spans.basis.push(r);
                }
            }
            "metric" => {
                let (rows, whole) = parse_list(input, |i| parse_list(i, parse_number))?;
                let mut m = Matrix {
                    whole,
                    rows: Vec::new(),
                    entries: Vec::new(),
                };
                let mut values = Vec::new();
                for (row, r) in rows {
                    m.rows.push(r);
                    values.push(row.iter().map(|e| e.0).collect());
                    m.entries.push(row.iter().map(|e| e.1).collect());
                }
                raw.metric = Some(values);
                spans.metric = Some(m);
            }
            "diagonal" => {
                let (entries, whole) = parse_list(input, parse_number)?;
                raw.diagonal = Some(entries.iter().map(|e| e.0).collect());
                spans.diagonal = Some(List {
                    whole,
                    entries: entries.iter().map(|e| e.1).collect(),
                });
            }
            "scalar" => {
                let t: Ident = input.parse()?;
                self.scalar = Some(match t.to_string().as_str() {
                    "f64" => ScalarType::F64,
                    "f32" => ScalarType::F32,
                    _ => return Err(syn::Error::new(t.span(), "expected `f32` or `f64`")),
                });
            }
            "runtime" => self.runtime = Some(parse_runtime(input)?),
            "exp_log" => {
                let t: Ident = input.parse()?;
                self.require_exp_log = match t.to_string().as_str() {
                    "required" => true,
                    "optional" => false,
                    _ => {
                        return Err(syn::Error::new(
                            t.span(),
                            "expected `required` or `optional`",
                        ))
                    }
                };
            }
            "path" => self.path = Some(input.parse()?),
            _ => {
                return Err(syn::Error::new(
                    key.span(),
                    format!("unknown key `{k}`: {EXPECTED_ITEM}"),
                ))
            }
        }
        self.seen.push((k, key_range));
        Ok(())
    }

    /// The input: a spec file (`path`, with only `scalar`, `runtime` and `exp_log` beside
    /// it) or the inline spec (which needs a basis).
    fn finish(self) -> syn::Result<Input> {
        let scalar = self.scalar.unwrap_or(ScalarType::F64);
        let (runtime, require_exp_log) = (self.runtime, self.require_exp_log);
        if let Some(path) = self.path {
            let clash = self
                .seen
                .iter()
                .find(|(k, _)| SPEC_KEYS.contains(&k.as_str()))
                .map(|(k, r)| (format!("`{k}`"), *r))
                .or_else(|| {
                    self.items
                        .map(|r| ("`type` and `sandwich` items".to_string(), r))
                });
            if let Some((what, range)) = clash {
                return Err(error_at(
                    range,
                    format!(
                        "{what} cannot be given with `path = ...`: the spec file gives the whole \
                         algebra (only `scalar`, `runtime` and `exp_log` may be added)"
                    ),
                ));
            }
            return Ok(Input {
                source: Source::File(path),
                scalar,
                runtime,
                require_exp_log,
            });
        }
        if self.spans.basis_list.is_none() {
            return Err(error_at(
                Range::call_site(),
                "missing `basis = [...]` (or `path = \"spec.toml\"` to read the spec from a file)",
            ));
        }
        let (raw, spans) = (self.raw, self.spans);
        Ok(Input {
            source: Source::Inline(Box::new(Inline { raw, spans })),
            scalar,
            runtime,
            require_exp_log,
        })
    }
}

/// The documentation in `#[doc = "..."]` attributes (doc comments), one line per attribute
/// with the leading space of `/// text` removed; an error for any other attribute.
fn doc_of(attrs: &[Attribute]) -> syn::Result<Option<(String, Range)>> {
    let mut lines = Vec::new();
    let mut range: Option<Range> = None;
    for a in attrs {
        let value = match &a.meta {
            syn::Meta::NameValue(nv) if nv.path.is_ident("doc") => match &nv.value {
                syn::Expr::Lit(syn::ExprLit {
                    lit: Lit::Str(s), ..
                }) => s.value(),
                _ => return Err(syn::Error::new_spanned(a, "expected a doc string")),
            },
            _ => {
                return Err(syn::Error::new_spanned(
                    a,
                    "only doc comments are allowed in `algebra!`",
                ))
            }
        };
        let r = Range::one(a.pound_token.span);
        range = Some(range.map_or(r, |first| first.to(r)));
        lines.push(value.strip_prefix(' ').unwrap_or(&value).to_string());
    }
    Ok(range.map(|r| (lines.join("\n"), r)))
}

/// A name: an identifier (keywords allowed) or a string literal.
fn parse_name(input: ParseStream) -> syn::Result<(String, Range)> {
    if input.peek(LitStr) {
        let s: LitStr = input.parse()?;
        Ok((s.value(), Range::one(s.span())))
    } else if input.peek(Ident::peek_any) {
        let i = input.call(Ident::parse_any)?;
        Ok((i.unraw().to_string(), Range::one(i.span())))
    } else {
        Err(input.error("expected a name (`e1`, `e12`, `s`, ...)"))
    }
}

/// A number: an optional `-` and an integer or float literal.
fn parse_number(input: ParseStream) -> syn::Result<(f64, Range)> {
    let minus: Option<Token![-]> = input.parse()?;
    let lit = if input.peek(syn::LitInt) || input.peek(syn::LitFloat) {
        input.parse::<Lit>()?
    } else {
        return Err(input.error("expected a number"));
    };
    let v: f64 = match &lit {
        Lit::Int(i) => i.base10_parse()?,
        Lit::Float(f) => f.base10_parse()?,
        _ => unreachable!("peeked a number"),
    };
    let end = Range::one(lit.span());
    match minus {
        Some(m) => Ok((-v, Range::one(m.span).to(end))),
        None => Ok((v, end)),
    }
}

/// `[item, item, ...]` (trailing comma allowed); the items and the range of the brackets.
fn parse_list<T>(
    input: ParseStream,
    item: impl Fn(ParseStream) -> syn::Result<T>,
) -> syn::Result<(Vec<T>, Range)> {
    let content;
    let bracket = bracketed!(content in input);
    let mut out = Vec::new();
    while !content.is_empty() {
        out.push(item(&content)?);
        if content.is_empty() {
            break;
        }
        content.parse::<Token![,]>()?;
    }
    Ok((out, Range::one(bracket.span.join())))
}

/// `type Name { blades = [..], constants = { blade = number, .. }, versor = bool, unit = bool,
/// doc = "..." }`.
fn parse_type(input: ParseStream, doc: Option<String>) -> syn::Result<(RawType, TypeSpans)> {
    input.parse::<Token![type]>()?;
    let name: Ident = input.parse()?;
    let mut t = RawType {
        name: name.to_string(),
        doc,
        ..RawType::default()
    };
    let mut s = TypeSpans {
        name: Range::one(name.span()),
        blades: Vec::new(),
        constants: Vec::new(),
    };
    let body;
    braced!(body in input);
    let mut seen: Vec<String> = Vec::new();
    while !body.is_empty() {
        let key = body.call(Ident::parse_any)?;
        let k = key.unraw().to_string();
        if seen.contains(&k) {
            return Err(syn::Error::new(
                key.span(),
                format!("`{k}` given twice for type `{name}`"),
            ));
        }
        body.parse::<Token![=]>()?;
        match k.as_str() {
            "blades" => {
                let (blades, _) = parse_list(&body, parse_name)?;
                for (b, r) in blades {
                    t.blades.push(b);
                    s.blades.push(r);
                }
            }
            "constants" => {
                let content;
                braced!(content in body);
                while !content.is_empty() {
                    let (b, r) = parse_name(&content)?;
                    content.parse::<Token![=]>()?;
                    let (v, vr) = parse_number(&content)?;
                    if t.constants.insert(b.clone(), v).is_some() {
                        return Err(error_at(
                            r,
                            format!("type `{name}`: constant on `{b}` given twice"),
                        ));
                    }
                    s.constants.push((b, r, vr));
                    if content.is_empty() {
                        break;
                    }
                    content.parse::<Token![,]>()?;
                }
            }
            "versor" => t.versor = body.parse::<syn::LitBool>()?.value,
            "unit" => t.unit = body.parse::<syn::LitBool>()?.value,
            "doc" => {
                let d: LitStr = body.parse()?;
                if t.doc.is_some() {
                    return Err(syn::Error::new(
                        key.span(),
                        format!("type `{name}` has both doc comments and `doc = ...`"),
                    ));
                }
                t.doc = Some(d.value());
            }
            _ => {
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown field `{k}` of type `{name}`: expected `blades`, `constants`, \
                         `versor`, `unit` or `doc`"
                    ),
                ))
            }
        }
        seen.push(k);
        if body.is_empty() {
            break;
        }
        body.parse::<Token![,]>()?;
    }
    Ok((t, s))
}

/// `sandwich Versor(Operand) -> Output` (the `sandwich` keyword already read) or
/// `sandwich Versor(Operand)` to infer the output.
fn parse_sandwich(input: ParseStream, keyword: Range) -> syn::Result<(RawSandwich, SandwichSpans)> {
    let versor: Ident = input.parse()?;
    let content;
    let paren = parenthesized!(content in input);
    let operand: Ident = content.parse()?;
    if !content.is_empty() {
        return Err(content.error("expected `)`: a sandwich has one operand type"));
    }
    let output: Option<Ident> = if input.peek(Token![->]) {
        input.parse::<Token![->]>()?;
        Some(input.parse()?)
    } else {
        None
    };
    let end = output
        .as_ref()
        .map_or(Range::one(paren.span.join()), |o| Range::one(o.span()));
    Ok((
        RawSandwich {
            versor: versor.to_string(),
            operand: operand.to_string(),
            output: output.as_ref().map(Ident::to_string),
        },
        SandwichSpans {
            whole: keyword.to(end),
            versor: Range::one(versor.span()),
            operand: Range::one(operand.span()),
            output: output.map(|o| Range::one(o.span())),
        },
    ))
}

/// `runtime = ::some::path`: the path generated code names the runtime crate by.
fn parse_runtime(input: ParseStream) -> syn::Result<String> {
    let p = input.call(syn::Path::parse_mod_style)?;
    let mut s = String::new();
    if p.leading_colon.is_some() {
        s.push_str("::");
    }
    let segs: Vec<String> = p.segments.iter().map(|s| s.ident.to_string()).collect();
    s.push_str(&segs.join("::"));
    Ok(s)
}
