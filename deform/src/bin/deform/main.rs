//! The `deform` program: the motor deformers of the CGA papers on procedural meshes (`demo`)
//! and on any mesh file (`spline`, `handles`, `fabrik`, `arap`, `ffd`, `cage`, `skin`, `cut`, `tear`, `drill`), with OBJ output,
//! PNG previews and timings. Exit code 0 on success, 2 on any error (bad arguments, unreadable
//! or invalid input, a failed write), with a message that says what and where.
//!
//! `cli` is the command line; `commands/` holds one file per subcommand (its arguments and its
//! `run`); the modules beside them are what the subcommands share, and never use a subcommand.

mod budget;
mod cli;
mod commands;
mod finish;
mod gpu_pose;
mod input_files;
mod interrupt;
mod numbers;
mod output_files;
mod progress;
mod report;
mod shared_args;
mod similarity_report;
mod surgery_io;
mod timing;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = match cli::Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let _ = e.print();
            if let Some(hint) = gpu_value_hint(std::env::args().skip(1)) {
                eprintln!("{hint}");
            }
            return if e.use_stderr() {
                ExitCode::from(2)
            } else {
                ExitCode::SUCCESS
            };
        }
    };
    budget::set(cli.max_work);
    interrupt::install();
    match cli.command.run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", message(&e));
            ExitCode::from(2)
        }
    }
}

/// The error and its causes joined by `": "`, as `{:#}` writes them, leaving out a cause that
/// its error's message already ends with (a file error says "PATH: REASON" and has REASON as
/// its cause: it was written twice).
fn message(e: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in e.chain() {
        let c = cause.to_string();
        if text.is_empty() {
            text = c;
        } else if !text.ends_with(&c) {
            text.push_str(": ");
            text.push_str(&c);
        }
    }
    text
}

/// `--gpu auto` (a space, not `=`): clap reads `auto` as the next positional argument, since
/// `--gpu` alone means `--gpu=on`; say how to write it.
fn gpu_value_hint(args: impl Iterator<Item = String>) -> Option<String> {
    let args: Vec<String> = args.collect();
    args.windows(2).find_map(|w| {
        (w[0] == "--gpu" && ["on", "off", "auto"].contains(&w[1].as_str())).then(|| {
            format!(
                "hint: --gpu takes its value after '=': write --gpu={}",
                w[1]
            )
        })
    })
}
