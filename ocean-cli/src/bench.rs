//! `ocean bench`: the suites of `ocean_bench` (BENCHMARKS.md), one or all, as tables or JSON.
//!
//! Times are medians over repeated runs after a warm-up; every figure is measured in the same
//! run as the baseline it is compared with.

use clap::Args;
use ocean_bench::timing::{cpu_name, utc_date};
use ocean_bench::{BenchOptions, Suite};
use serde_json::{Value, json};

#[derive(Args)]
pub struct BenchArgs {
    /// Which suite to run.
    suite: Suite,
    /// Print one JSON document instead of a table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub options: BenchOptions,
}

pub fn run(args: &BenchArgs) -> Result<(), String> {
    let json = |v: &Value| serde_json::to_string_pretty(v).map_err(|e| e.to_string());
    if !matches!(args.suite, Suite::All) {
        let doc = args.suite.report(&args.options)?;
        if args.json {
            println!("{}", json(&doc)?);
        } else {
            args.suite.print(&doc);
        }
        return Ok(());
    }
    let started = std::time::Instant::now();
    let mut suites = serde_json::Map::new();
    for suite in Suite::ALL {
        if crate::interrupt::requested() {
            return Err(crate::interrupt::MESSAGE.to_owned());
        }
        let t = std::time::Instant::now();
        let doc = suite.report(&args.options)?;
        if !args.json {
            println!("== {} ({:.1} s)", suite.name(), t.elapsed().as_secs_f64());
            suite.print(&doc);
            println!();
        }
        suites.insert(suite.name().to_owned(), doc);
    }
    if args.json {
        let doc = json!({
            "suite": "all",
            "date": utc_date(std::time::SystemTime::now()),
            "cpu": cpu_name(),
            "threads": rayon::current_num_threads(),
            "os": std::env::consts::OS,
            "wall_s": started.elapsed().as_secs_f64(),
            "suites": suites,
        });
        println!("{}", json(&doc)?);
    }
    Ok(())
}
