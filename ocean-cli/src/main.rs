//! `ocean`: the command-line front end of the ocean crates.
#![forbid(unsafe_code)]

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use ocean_cli::{bench, cone_map, interrupt, render, shaders};

/// Real-time water and screen-space rendering: scene renders, benchmarks, shader export, cone
/// maps.
#[derive(Parser)]
#[command(name = "ocean", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene (the built-in one or a TOML file) into PNG images, headless.
    Render(render::RenderArgs),
    /// Run a benchmark suite and print its figures.
    Bench(bench::BenchArgs),
    /// Export every WGSL pass to another shading language, with its binding layout.
    Shaders(shaders::ShadersArgs),
    /// Generate a relief texture (depth and relaxed or conservative cone maps) from a
    /// height-map PNG.
    #[command(after_long_help = cone_map::FORMAT)]
    ConeMap(cone_map::ConeMapArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Shaders(args) => shaders::run(&args),
        Command::ConeMap(args) => cone_map::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("ocean: {e}");
            if interrupt::requested() {
                // The shell's status for a job stopped by SIGINT (128 + 2).
                ExitCode::from(130)
            } else {
                ExitCode::FAILURE
            }
        }
    }
}
