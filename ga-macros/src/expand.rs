//! The expansion: input tokens -> spec -> `ga_codegen::generate` -> tokens (as generated: no
//! formatting and no string round trip).

use crate::grammar::{error_at, Input, Source};
use crate::locate;
use ga_codegen::{generate, EmitOptions, Spec};
use proc_macro2::TokenStream;
use std::path::PathBuf;
use syn::LitStr;

/// What an inline spec is called in the generated header and in errors.
pub(crate) const INLINE_SOURCE: &str = "algebra!";

/// Expand `algebra!` input into the generated items, or the error to report.
pub(crate) fn expand(tokens: TokenStream) -> syn::Result<TokenStream> {
    let first = tokens
        .clone()
        .into_iter()
        .next()
        .map_or_else(proc_macro2::Span::call_site, |t| t.span());
    let input: Input = syn::parse2(tokens)?;
    let mut opts = EmitOptions {
        scalar: input.scalar,
        require_exp_log: input.require_exp_log,
        ..EmitOptions::default()
    };
    if let Some(rt) = input.runtime {
        opts.runtime = rt;
    }
    match input.source {
        Source::File(lit) => expand_file(&lit, &opts, first),
        Source::Inline(inline) => {
            let spec = Spec::from_raw(inline.raw.clone(), INLINE_SOURCE).map_err(|e| {
                let at = locate::spec_error(&e, &inline.spans);
                error_at(at, without_source(&e.to_string()))
            })?;
            let generated = generate(&spec, &opts).map_err(|e| {
                let at = locate::gen_error(&e, &inline.raw, &inline.spans);
                error_at(at, without_source(&e.to_string()))
            })?;
            Ok(located(generated.tokens, first))
        }
    }
}

/// `path = "spec.toml"`: read the file relative to the calling crate's manifest directory.
/// Every error points at the path literal and names the file.
fn expand_file(
    lit: &LitStr,
    opts: &EmitOptions,
    at: proc_macro2::Span,
) -> syn::Result<TokenStream> {
    let written = lit.value();
    let path = match std::env::var_os("CARGO_MANIFEST_DIR") {
        Some(dir) => PathBuf::from(dir).join(&written),
        None => PathBuf::from(&written),
    };
    let text = std::fs::read_to_string(&path).map_err(|e| {
        // The OS's wording of "not found" differs between platforms; say it one way.
        let why = if e.kind() == std::io::ErrorKind::NotFound {
            "no such file".to_string()
        } else {
            e.to_string()
        };
        syn::Error::new(
            lit.span(),
            format!(
                "cannot read spec file `{written}`: {why} (the path is relative to the directory \
                 of the calling crate's Cargo.toml)"
            ),
        )
    })?;
    // Name the spec as written, as the CLI does, so errors and the generated header read the
    // same as `ga-codegen <path>` run from the crate's directory.
    let spec = Spec::from_toml(&text, &written).map_err(|e| syn::Error::new(lit.span(), e))?;
    let generated = generate(&spec, opts).map_err(|e| syn::Error::new(lit.span(), e))?;
    let mut out = located(generated.tokens, at);
    // Make the compiler track the file, so that editing the spec re-expands the macro.
    if let Some(abs) = path.to_str().filter(|_| path.is_absolute()) {
        out.extend(quote::quote! {
            const _: &[u8] = ::core::include_bytes!(#abs);
        });
    }
    Ok(out)
}

/// The generated tokens with call-site hygiene but located at one token of the input (`at`).
/// A single-line location matters: clippy's `possible_missing_comma` reads the source between
/// the tokens of an array element, and with the whole (multi-line) invocation as location it
/// would find line breaks there and fire on generated matrices.
fn located(tokens: TokenStream, at: proc_macro2::Span) -> TokenStream {
    respan(tokens, proc_macro2::Span::call_site().located_at(at))
}

fn respan(tokens: TokenStream, span: proc_macro2::Span) -> TokenStream {
    use proc_macro2::{Group, TokenTree};
    tokens
        .into_iter()
        .map(|mut t| {
            if let TokenTree::Group(g) = &t {
                let mut ng = Group::new(g.delimiter(), respan(g.stream(), span));
                ng.set_span(span);
                t = TokenTree::Group(ng);
            } else {
                t.set_span(span);
            }
            t
        })
        .collect()
}

/// An error message without the `algebra!: ` prefix naming the source: for an inline spec
/// the error already points into the macro.
fn without_source(message: &str) -> String {
    message
        .strip_prefix(INLINE_SOURCE)
        .and_then(|m| m.strip_prefix(": "))
        .unwrap_or(message)
        .to_string()
}
