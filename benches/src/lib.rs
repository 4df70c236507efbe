//! Benchmarks (criterion, in `benches/benches/`) and the quick bench report binary
//! (`cargo run --release -p benches --bin bench-report`).
pub mod cga_report;
pub mod codegen_report;
#[path = "../../deform/benches/grade.rs"]
pub mod grade;
pub mod timing;
