//! Benchmarks (criterion, in `benches/benches/`) and the quick bench report binary.
