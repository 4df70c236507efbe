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
    ("surgery", &["mesh", "blend", "skinning"]),
    ("render", &["mesh"]),
    ("input", &["mesh"]),
    ("gpu", &["mesh", "blend"]),
    (
        "methods",
        &[
            "mesh",
            "operators",
            "blend",
            "deformers",
            "skinning",
            "surgery",
            "render",
            "input",
        ],
    ),
    (
        "editor",
        &[
            "mesh",
            "operators",
            "blend",
            "deformers",
            "skinning",
            "surgery",
            "render",
            "input",
            "methods",
        ],
    ),
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

/// The files of one crate (the library, or the program) as modules: path segments from the
/// crate root, the `mod` children each declares, and what each re-exports.
struct ModuleTree {
    files: Vec<(PathBuf, Vec<String>)>,
}

impl ModuleTree {
    /// `root` is `lib.rs` or `main.rs`; every `.rs` file under its folder (but not under
    /// `skip`) is a module named by its path.
    fn new(dir: &Path, skip: Option<&Path>) -> Self {
        let mut paths = Vec::new();
        rust_files(dir, &mut paths);
        let files = paths
            .into_iter()
            .filter(|p| skip.is_none_or(|s| !p.starts_with(s)))
            .map(|p| {
                let rel = p
                    .strip_prefix(dir)
                    .expect("under the root")
                    .with_extension("");
                let mut segs: Vec<String> = rel
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().into_owned())
                    .collect();
                if matches!(
                    segs.last().map(String::as_str),
                    Some("mod" | "lib" | "main")
                ) {
                    segs.pop();
                }
                (p, segs)
            })
            .collect();
        ModuleTree { files }
    }

    fn file_of(&self, module: &[String]) -> Option<usize> {
        self.files.iter().position(|(_, m)| m == module)
    }
}

/// `a::{b, c::{d, e as f}, self}` -> `a::b`, `a::c::d`, `a::c::e`, `a`.
fn expand_use(tree: &str) -> Vec<String> {
    let tree: String = tree.split_whitespace().collect::<Vec<_>>().join(" ");
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or("").trim();
        return vec![path.to_string()];
    };
    let prefix = tree[..open].trim_end_matches("::").trim().to_string();
    let body = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let mut items = Vec::new();
    let (mut depth, mut start) = (0usize, 0);
    for (k, c) in body.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&body[start..k]);
                start = k + 1;
            }
            _ => {}
        }
    }
    items.push(&body[start..]);
    let mut out = Vec::new();
    for item in items.into_iter().map(str::trim).filter(|i| !i.is_empty()) {
        if item == "self" {
            out.push(prefix.clone());
        } else {
            out.extend(expand_use(&format!("{prefix}::{item}")));
        }
    }
    out
}

/// The code of a file without comments and without its `#[cfg(test)] mod tests` (tests may
/// reach anywhere in their file's module).
fn module_code(file: &Path) -> String {
    let code = strip_comments(&std::fs::read_to_string(file).expect("readable"));
    match code.find("#[cfg(test)]\nmod tests") {
        Some(i) => code[..i].to_string(),
        None => code,
    }
}

/// Every path a file names: the expanded `use` declarations (with whether they are
/// re-exports) and the inline `crate::`, `super::` and `self::` paths.
fn named_paths(code: &str) -> Vec<(String, bool)> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("use ") {
        let before = rest[..i].trim_end();
        let boundary = rest[..i]
            .chars()
            .next_back()
            .is_none_or(|c| !c.is_alphanumeric() && c != '_');
        let Some(end) = rest[i..].find(';') else {
            break;
        };
        if boundary {
            let public = before.ends_with("pub") || before.ends_with(')');
            for p in expand_use(&rest[i + 4..i + end]) {
                out.push((p, public));
            }
        }
        rest = &rest[i + end.max(1)..];
    }
    for head in ["crate::", "super::", "self::"] {
        for (i, _) in code.match_indices(head) {
            if code[..i]
                .chars()
                .next_back()
                .is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':' || c == '$')
            {
                continue;
            }
            let path: String = code[i..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            out.push((path.trim_end_matches(':').to_string(), false));
        }
    }
    out
}

/// The file a path leads to, following re-exports (`pub use`) to where the item is defined.
fn resolve(
    tree: &ModuleTree,
    exports: &[Vec<(String, String)>],
    children: &[Vec<String>],
    from: usize,
    path: &str,
    depth: usize,
) -> Option<usize> {
    let here = &tree.files[from].1;
    let mut segs: Vec<&str> = path.split("::").collect();
    let mut base: Vec<String> = match segs[0] {
        "crate" => {
            segs.remove(0);
            Vec::new()
        }
        "self" => {
            segs.remove(0);
            here.clone()
        }
        "super" => {
            let mut b = here.clone();
            while segs.first() == Some(&"super") {
                b.pop();
                segs.remove(0);
            }
            b
        }
        first if children[from].iter().any(|c| c == first) => here.clone(),
        _ => return None,
    };
    let full = base.len();
    for k in (0..=segs.len()).rev() {
        base.truncate(full);
        base.extend(segs[..k].iter().map(|s| s.to_string()));
        let Some(file) = tree.file_of(&base) else {
            continue;
        };
        if let Some(name) = segs.get(k) {
            if depth < 8 {
                if let Some((_, target)) = exports[file].iter().find(|(n, _)| n == name) {
                    if let Some(f) = resolve(tree, exports, children, file, target, depth + 1) {
                        return Some(f);
                    }
                }
            }
        }
        return Some(file);
    }
    None
}

/// A cycle of files that use each other (a module and the files below it excepted: a parent
/// declares its children and re-exports them).
fn file_cycle(tree: &ModuleTree) -> Option<Vec<String>> {
    let codes: Vec<String> = tree.files.iter().map(|(p, _)| module_code(p)).collect();
    let children: Vec<Vec<String>> = codes
        .iter()
        .map(|c| {
            c.lines()
                .filter_map(|l| {
                    let l = l.trim();
                    let l = l
                        .strip_prefix("pub ")
                        .or(l.strip_prefix("pub(crate) "))
                        .unwrap_or(l);
                    l.strip_prefix("mod ")?
                        .strip_suffix(';')
                        .map(str::to_string)
                })
                .collect()
        })
        .collect();
    let exports: Vec<Vec<(String, String)>> = codes
        .iter()
        .map(|c| {
            named_paths(c)
                .into_iter()
                .filter(|(_, public)| *public)
                .map(|(p, _)| (p.rsplit("::").next().unwrap_or("").to_string(), p))
                .collect()
        })
        .collect();
    let n = tree.files.len();
    let mut edges = vec![BTreeSet::new(); n];
    for from in 0..n {
        for (path, _) in named_paths(&codes[from]) {
            if let Some(to) = resolve(tree, &exports, &children, from, &path, 0) {
                let (a, b) = (&tree.files[from].1, &tree.files[to].1);
                let related = a.starts_with(b) || b.starts_with(a);
                if to != from && !related {
                    edges[from].insert(to);
                }
            }
        }
    }
    // Depth-first search for a back edge.
    let mut state = vec![0u8; n];
    let mut stack = Vec::new();
    fn visit(
        v: usize,
        edges: &[BTreeSet<usize>],
        state: &mut [u8],
        stack: &mut Vec<usize>,
    ) -> Option<Vec<usize>> {
        state[v] = 1;
        stack.push(v);
        for &w in &edges[v] {
            if state[w] == 1 {
                let at = stack.iter().position(|&x| x == w).expect("on the stack");
                return Some(stack[at..].to_vec());
            }
            if state[w] == 0 {
                if let Some(c) = visit(w, edges, state, stack) {
                    return Some(c);
                }
            }
        }
        stack.pop();
        state[v] = 2;
        None
    }
    (0..n)
        .find_map(|v| {
            if state[v] == 0 {
                visit(v, &edges, &mut state, &mut stack)
            } else {
                None
            }
        })
        .map(|c| {
            c.iter()
                .map(|&i| tree.files[i].0.display().to_string())
                .collect()
        })
}

#[test]
fn no_two_files_use_each_other() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let bin = src.join("bin");
    let library = ModuleTree::new(&src, Some(&bin));
    let program = ModuleTree::new(&bin.join("deform"), None);
    assert!(library.files.len() > 50 && program.files.len() > 10);
    for tree in [&library, &program] {
        if let Some(cycle) = file_cycle(tree) {
            panic!("files that use each other: {}", cycle.join(" -> "));
        }
    }
}

#[test]
fn the_cycle_finder_finds_a_cycle_through_a_re_export() {
    let dir = std::env::temp_dir().join(format!("deform-layering-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("m")).expect("dir");
    let write = |f: &str, s: &str| std::fs::write(dir.join(f), s).expect("write");
    write("lib.rs", "pub mod m;\n");
    write("m/mod.rs", "mod a;\nmod b;\npub use a::A;\npub use b::B;\n");
    write("m/a.rs", "use super::B;\npub struct A(B);\n");
    write("m/b.rs", "use crate::m::a::A;\npub struct B(Box<A>);\n");
    let cycle = file_cycle(&ModuleTree::new(&dir, None)).expect("a cycle");
    assert_eq!(cycle.len(), 2, "{cycle:?}");
    write("m/b.rs", "pub struct B;\n");
    assert_eq!(file_cycle(&ModuleTree::new(&dir, None)), None);
    let _ = std::fs::remove_dir_all(&dir);
}
