//! `ltc-lab`: parses the command line and hands each subcommand to its module in `cli/`.
//! Exit codes: 0 done, 1 the machine failed, 2 bad input (clap's usage errors exit 2 too),
//! 130 interrupted (SIGINT, SIGTERM or SIGHUP), with every unfinished output removed.

mod cli;

use std::process::ExitCode;

use clap::Parser;

use cli::{Cli, Command};

fn main() -> ExitCode {
    let cli = Cli::parse();
    // A signal would end the process without running any Drop, leaving temporary files,
    // claimed default names and directories made for outputs behind; the handler removes
    // them (see ltc_lab::files) and exits 128 + SIGINT.
    let handler = ctrlc::set_handler(|| {
        // Standard error may be held back while an adapter opens: the message must be seen.
        drop(ltc_lab::gpu::driver_output::give_back());
        ltc_lab::files::exit_interrupted(130, |n| {
            let s = if n == 1 { "" } else { "s" };
            eprintln!("ltc-lab: interrupted; removed {n} unfinished output{s}");
        })
    });
    if let Err(e) = handler {
        eprintln!("ltc-lab: note: an interrupt will not clean up ({e})");
    }
    let result = match cli.command {
        None => cli::lab::run(&cli::lab::Args::default()),
        Some(Command::Lab(a)) => cli::lab::run(&a),
        Some(Command::Fit(a)) => cli::fit::run(&a),
        Some(Command::Eval(a)) => cli::eval::run(&a),
        Some(Command::Lut(a)) => cli::lut::run(&a),
        Some(Command::Render(a)) => cli::render::run(&a),
        Some(Command::Bench(a)) => cli::bench::run(&a),
        Some(Command::Study(a)) => cli::study::run(&a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("ltc-lab: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
