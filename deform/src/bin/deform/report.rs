//! What a command prints at the end: its counts and timings, as aligned lines or (with
//! `--json`) one JSON object on stdout; nothing with `--quiet`.

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
    pub fn print(&self, out: &OutputArgs) {
        if out.json {
            let map: serde_json::Map<String, serde_json::Value> = self
                .fields
                .iter()
                .map(|(k, v)| (k.to_string(), v.clone()))
                .collect();
            println!("{}", serde_json::Value::Object(map));
        } else if !out.quiet {
            for (k, v) in &self.fields {
                println!("{k:>12}: {v}");
            }
        }
    }
}
