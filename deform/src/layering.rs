//! The layer rule, checked on the source: a file may name (through `crate::` paths, in `use`
//! declarations or inline) only its own layer and the layers below it. Comments are not
//! code, so doc links are free to point anywhere.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Each layer (a folder of `src/`) and the layers it may use.
const LAYERS: &[(&str, &[&str])] = &[
    ("mesh", &[]),
    ("operators", &["mesh"]),
    ("blend", &["mesh"]),
    ("deformers", &["mesh", "operators", "blend"]),
    ("skinning", &["mesh", "operators", "blend", "deformers"]),
    ("surgery", &["mesh", "skinning"]),
    ("render", &["mesh"]),
    ("input", &["mesh"]),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src is readable") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The source without comments (line comments, doc comments and block comments).
fn strip_comments(source: &str) -> String {
    let mut out = String::with_capacity(source.len());
    let mut rest = source;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix("//") {
            rest = r.find('\n').map_or("", |i| &r[i..]);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.find("*/").map_or("", |i| &r[i + 2..]);
        } else if rest.starts_with('"') {
            // Skip string literals, so "//" inside one is not a comment.
            let end = rest[1..]
                .char_indices()
                .scan(false, |escaped, (i, c)| {
                    let done = c == '"' && !*escaped;
                    *escaped = c == '\\' && !*escaped;
                    Some((i, done))
                })
                .find(|&(_, done)| done)
                .map_or(rest.len(), |(i, _)| i + 2);
            out.push_str(&rest[..end]);
            rest = &rest[end..];
        } else {
            let c = rest.chars().next().expect("not empty");
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// The first segment after every `crate::` in the code, including each item of a
/// `crate::{a, b::c}` group.
fn crate_paths(code: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let ident = |s: &str| -> String {
        s.trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    for (i, _) in code.match_indices("crate::") {
        let before = code[..i].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
            continue;
        }
        let after = &code[i + "crate::".len()..];
        if let Some(group) = after.strip_prefix('{') {
            // Top-level items of the group.
            let mut depth = 0usize;
            let mut start = 0;
            for (k, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        found.insert(ident(&group[start..k]));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        found.insert(ident(&group[start..k]));
                        start = k + 1;
                    }
                    _ => {}
                }
            }
        } else {
            found.insert(ident(after));
        }
    }
    found.remove("");
    found
}

#[test]
fn no_file_uses_a_layer_above_its_own() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut violations = Vec::new();
    let mut checked = 0;
    for file in &files {
        let rel = file.strip_prefix(&src).expect("under src");
        let layer = rel
            .components()
            .next()
            .and_then(|c| c.as_os_str().to_str())
            .expect("a file name");
        let Some((_, allowed)) = LAYERS.iter().find(|(name, _)| *name == layer) else {
            // lib.rs, error.rs, layering.rs and the program sit above every layer.
            assert!(
                ["lib.rs", "error.rs", "layering.rs", "bin"].contains(&layer),
                "{} is in no layer: add its folder to LAYERS",
                rel.display()
            );
            continue;
        };
        checked += 1;
        let code = strip_comments(&std::fs::read_to_string(file).expect("readable"));
        for used in crate_paths(&code) {
            if used != layer && !allowed.contains(&used.as_str()) {
                violations.push(format!("{} uses crate::{used}", rel.display()));
            }
        }
    }
    assert!(checked > 50, "only {checked} layer files found");
    assert!(
        violations.is_empty(),
        "files that name a layer above their own or a crate-level item (use the layer's \
         path):\n{}",
        violations.join("\n")
    );
}

#[test]
fn the_checker_sees_groups_inline_paths_and_not_comments() {
    let code = strip_comments(
        "use crate::{mesh::Mesh, blend::{A, B}};\n// crate::surgery in a comment\n\
         /// [`crate::render`]\nlet s = \"// not a comment\"; fn f() -> crate::skinning::X {}\n\
         use crate::Error;",
    );
    let found: Vec<String> = crate_paths(&code).into_iter().collect();
    assert_eq!(found, ["Error", "blend", "mesh", "skinning"]);
}
