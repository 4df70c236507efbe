//! The `deform` program: the motor deformers of the CGA papers on procedural meshes (`demo`)
//! and on any mesh file (`spline`, `handles`, `fabrik`, `arap`, `ffd`, `cage`, `skin`, `cut`, `tear`, `drill`), with OBJ output,
//! PNG previews and timings. Exit code 0 on success, 2 on any error (bad arguments, unreadable
//! or invalid input, a failed write), with a message that says what and where.

mod arap_cmd;
mod args;
mod budget;
mod commands;
mod demo;
mod interrupt;
mod lattice_cmds;
mod lattice_demo;
mod numbers;
mod output;
mod preview;
mod skin_cmd;
mod surgery_cmds;
mod surgery_demo;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() {
                ExitCode::from(2)
            } else {
                ExitCode::SUCCESS
            };
        }
    };
    budget::set(cli.max_work);
    interrupt::install();
    let result = match cli.command {
        args::Command::Demo(a) => demo::run(&a),
        args::Command::Spline(a) => commands::spline(&a),
        args::Command::Handles(a) => commands::handles(&a),
        args::Command::Fabrik(a) => commands::fabrik(&a),
        args::Command::Ffd(a) => lattice_cmds::ffd(&a),
        args::Command::Cage(a) => lattice_cmds::cage(&a),
        args::Command::Arap(a) => arap_cmd::arap(&a),
        args::Command::Skin(a) => skin_cmd::skin(&a),
        args::Command::Cut(a) => surgery_cmds::cut(&a),
        args::Command::Drill(a) => surgery_cmds::drill(&a),
        args::Command::Tear(a) => surgery_cmds::tear(&a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
