//! What a command prints at the end: its counts and timings, as aligned lines for people
//! (numbers short, strings bare) or (with `--json`) one JSON object on stdout, every number
//! in full, the notes as one array `notes`); nothing with `--quiet`.

use crate::shared_args::OutputArgs;
use deform::Mesh;

/// Counts and timings, printed as lines or one JSON object.
pub struct Report {
    pub fields: Vec<(&'static str, serde_json::Value)>,
}

impl Report {
    pub fn new(command: &str, mesh: &Mesh) -> Report {
        Report {
            fields: vec![
                ("command", command.into()),
                ("vertices", mesh.vertex_count().into()),
                ("triangles", mesh.triangle_count().into()),
            ],
        }
    }
    pub fn add(&mut self, key: &'static str, value: impl Into<serde_json::Value>) {
        self.fields.push((key, value.into()));
    }
    /// The fields as one JSON object; the notes (every `note` added) as one array `notes`.
    pub fn json(&self) -> serde_json::Value {
        let mut map = serde_json::Map::new();
        let mut notes = Vec::new();
        for (k, v) in &self.fields {
            if *k == "note" {
                notes.push(v.clone());
            } else {
                map.insert(k.to_string(), v.clone());
            }
        }
        if !notes.is_empty() {
            map.insert("notes".into(), notes.into());
        }
        serde_json::Value::Object(map)
    }

    pub fn print(&self, out: &OutputArgs) {
        if out.json {
            println!("{}", self.json());
        } else if !out.quiet {
            // Values in one column; a key longer than 22 characters pushes its own value out.
            let width = self
                .fields
                .iter()
                .map(|(k, _)| k.len() + 1)
                .max()
                .unwrap_or(0);
            let width = width.min(23);
            for (k, v) in &self.fields {
                println!("{:<width$} {}", format!("{k}:"), human(v));
            }
        }
    }
}

/// A value as the aligned lines show it: numbers in about four significant digits
/// (`deform::render::short_number`; integers whole), strings without quotes (unless they hold
/// a control character), lists and
/// objects with their items shown the same way.
fn human(v: &serde_json::Value) -> String {
    use serde_json::Value;
    match v {
        Value::Number(n) if n.is_f64() => n
            .as_f64()
            .map_or_else(|| n.to_string(), deform::render::short_number),
        // Quoted and escaped when it holds a control character (a file name with a newline or
        // a terminal escape), bare otherwise.
        Value::String(s) if s.chars().any(char::is_control) => v.to_string(),
        Value::String(s) => s.clone(),
        Value::Array(items) => {
            let items: Vec<String> = items.iter().map(human).collect();
            format!("[{}]", items.join(", "))
        }
        Value::Object(map) => {
            let items: Vec<String> = map
                .iter()
                .map(|(k, v)| format!("{k}: {}", human(v)))
                .collect();
            format!("{{{}}}", items.join(", "))
        }
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::human;
    use serde_json::json;

    #[test]
    fn people_read_short_numbers_and_bare_strings() {
        assert_eq!(human(&json!(2.0734310000000002)), "2.073");
        assert_eq!(human(&json!(0.01726)), "0.01726");
        assert_eq!(human(&json!(3.2e-15)), "3.20e-15");
        assert_eq!(human(&json!(49999)), "49999");
        assert_eq!(human(&json!("skin")), "skin");
        assert_eq!(
            human(&json!({"loops": [1, 2.5], "path": "a b.obj"})),
            "{loops: [1, 2.5], path: a b.obj}"
        );
        assert_eq!(human(&json!(null)), "null");
        assert_eq!(human(&json!("a\nb\u{1b}[2J")), "\"a\\nb\\u001b[2J\"");
    }
}
