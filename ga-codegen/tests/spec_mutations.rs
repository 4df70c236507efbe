//! Mutation test over the shipped specs in `algebras/`: thousands of deterministic mutations
//! (numbers replaced by huge, tiny, negative, NaN and infinite values, blade and type names
//! changed, lines deleted, duplicated and swapped, bytes flipped, files truncated) are parsed,
//! and those that parse are generated. The promise: a typed error or generated code, never a
//! panic. Runs in a few seconds. The words include the hostile user's: keyword and colliding
//! basis names, generated helper names as type names, decimal and overflowing metric entries.

use ga_codegen::{generate, EmitOptions, Spec};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// A small deterministic generator (64-bit LCG, high bits out).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

const NUMBERS: &[&str] = &[
    "1e308",
    "-1e308",
    "1e-320",
    "0",
    "-0.0",
    "nan",
    "inf",
    "-inf",
    "170141183460469231731687303715884105727",
    "9223372036854775807",
    "0.1",
    "1e-17",
    "3",
    "-2",
    "12345678901234567",
    "0.3333333333333333",
    "1e13",
    "1e-9",
    "0.7",
];

const WORDS: &[&str] = &[
    "\"e\"",
    "\"s\"",
    "\"e1\"",
    "\"e11\"",
    "\"eoi\"",
    "\"eq\"",
    "\"\"",
    "\"Motor\"",
    "\"Vector\"",
    "\"Mv\"",
    "\"fn\"",
    "\"e123456789\"",
    "\"é\"",
    "true",
    "[]",
    "[[]]",
    "{}",
    "\"enum\"",
    "\"else\"",
    "\"e12\"",
    "\"RVMatrix\"",
    "\"MotorPointMatrix\"",
    "\"Scalar\"",
];

/// Positions of the numbers (runs of digits, signs, dots and exponents) in `text`.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() && (i == 0 || !b[i - 1].is_ascii_alphanumeric()) {
            let start = if i > 0 && b[i - 1] == b'-' { i - 1 } else { i };
            let mut j = i;
            while j < b.len() && (b[j].is_ascii_digit() || b"._eE-+".contains(&b[j])) {
                j += 1;
            }
            spans.push((start, j));
            i = j;
        } else {
            i += 1;
        }
    }
    spans
}

/// Positions of the quoted strings in `text`.
fn string_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'"' {
            if let Some(len) = b[i + 1..].iter().position(|&c| c == b'"') {
                spans.push((i, i + len + 2));
                i += len + 2;
                continue;
            }
        }
        i += 1;
    }
    spans
}

fn replace_span(text: &str, (a, b): (usize, usize), with: &str) -> String {
    format!("{}{}{}", &text[..a], with, &text[b..])
}

/// One mutation of `text` (always valid UTF-8; TOML is text).
fn mutate(text: &str, rng: &mut Lcg) -> String {
    let lines: Vec<&str> = text.lines().collect();
    match rng.below(8) {
        0 => {
            let spans = number_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let s = spans[rng.below(spans.len())];
            replace_span(text, s, NUMBERS[rng.below(NUMBERS.len())])
        }
        1 | 2 => {
            let spans = string_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let s = spans[rng.below(spans.len())];
            replace_span(text, s, WORDS[rng.below(WORDS.len())])
        }
        3 => {
            let k = rng.below(lines.len());
            let mut l = lines.clone();
            l.remove(k);
            l.join("\n")
        }
        4 => {
            let k = rng.below(lines.len());
            let mut l = lines.clone();
            l.insert(k, lines[k]);
            l.join("\n")
        }
        5 => {
            let (i, j) = (rng.below(lines.len()), rng.below(lines.len()));
            let mut l = lines.clone();
            l.swap(i, j);
            l.join("\n")
        }
        6 => {
            let mut cut = rng.below(text.len());
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            text[..cut].to_string()
        }
        _ => {
            let mut bytes = text.as_bytes().to_vec();
            let k = rng.below(bytes.len());
            bytes[k] = b"[]{}=,\"#-.0123456789e \n"[rng.below(23)];
            String::from_utf8_lossy(&bytes).into_owned()
        }
    }
}

#[test]
fn mutated_specs_give_typed_errors_or_code_never_a_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras");
    let mut specs: Vec<_> = std::fs::read_dir(&dir)
        .expect("algebras/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    specs.sort();
    assert!(specs.len() >= 4, "expected the four shipped specs");
    let mut rng = Lcg(0x5eed_cafe);
    let (mut parsed, mut rejected, mut generated) = (0, 0, 0);
    for path in &specs {
        let original = std::fs::read_to_string(path).expect("read spec");
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        // Parsing is cheap and every mutation is parsed; generating takes a moment (all of
        // G(4,1) about a second in a test build), so a sample of the mutations that parse is
        // generated: one in nine (singly mutated) for the small algebras, a few for cga.
        let big = original.len() > 3000;
        for k in 0..500 {
            let mut text = mutate(&original, &mut rng);
            if k % 3 == 0 {
                text = mutate(&text, &mut rng);
            }
            let gen_this = if big { k % 100 == 0 } else { k % 9 == 1 };
            let outcome = catch_unwind(AssertUnwindSafe(|| match Spec::from_toml(&text, &name) {
                Ok(spec) => {
                    if gen_this {
                        let code = generate(&spec, &EmitOptions::default())
                            .and_then(|g| g.code().map(str::to_string));
                        if let Ok(code) = code {
                            assert!(!code.is_empty());
                            return (1, 0, 1);
                        }
                    }
                    (1, 0, 0)
                }
                Err(e) => {
                    assert!(!e.to_string().is_empty());
                    (0, 1, 0)
                }
            }));
            match outcome {
                Ok((p, r, g)) => {
                    parsed += p;
                    rejected += r;
                    generated += g;
                }
                Err(_) => panic!("{name}, mutation {k} panicked; spec:\n{text}"),
            }
        }
    }
    // The mutations must exercise both paths, or the test proves nothing.
    assert!(
        parsed > 100 && rejected > 100,
        "{parsed} parsed, {rejected} rejected"
    );
    assert!(generated > 40, "{generated} generated");
}
