//! Which names can become Rust identifiers in generated code.

/// Every Rust keyword, strict and reserved, in all editions (`gen` from 2024, `try` from 2018,
/// `async`/`await`/`dyn` from 2018), plus `union` and `macro_rules`, which are contextual but
/// break an item named so.
const KEYWORDS: &[&str] = &[
    "Self",
    "abstract",
    "as",
    "async",
    "await",
    "become",
    "box",
    "break",
    "const",
    "continue",
    "crate",
    "do",
    "dyn",
    "else",
    "enum",
    "extern",
    "false",
    "final",
    "fn",
    "for",
    "gen",
    "if",
    "impl",
    "in",
    "let",
    "loop",
    "macro",
    "macro_rules",
    "match",
    "mod",
    "move",
    "mut",
    "override",
    "priv",
    "pub",
    "ref",
    "return",
    "self",
    "static",
    "struct",
    "super",
    "trait",
    "true",
    "try",
    "type",
    "typeof",
    "union",
    "unsafe",
    "unsized",
    "use",
    "virtual",
    "where",
    "while",
    "yield",
];

/// True when `name` is a Rust keyword and so cannot be a field, method or type name.
pub fn is_keyword(name: &str) -> bool {
    KEYWORDS.contains(&name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keywords_are_recognised() {
        for k in ["enum", "else", "extern", "Self", "gen", "fn"] {
            assert!(is_keyword(k), "{k}");
        }
        for n in ["e1", "eo", "Motor", "self_", "Enum"] {
            assert!(!is_keyword(n), "{n}");
        }
    }
}
