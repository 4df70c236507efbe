//! Quick bench report: prints the ratio tables of the generator and of the `cga` crate (GA
//! against glam matrix code, generated against generic) in well under a minute.
//!
//! `cargo run --release -p benches --bin bench-report [codegen|cga]`

fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    let start = std::time::Instant::now();
    if which.is_empty() || which == "codegen" {
        println!("== ga-codegen ==");
        print!("{}", benches::codegen_report::report());
    }
    if which.is_empty() || which == "cga" {
        println!("\n== cga ==");
        print!("{}", benches::cga_report::report());
    }
    if !matches!(which.as_str(), "" | "codegen" | "cga") {
        eprintln!("usage: bench-report [codegen|cga]");
        std::process::exit(2);
    }
    println!("\nreport took {:.1} s", start.elapsed().as_secs_f64());
}
