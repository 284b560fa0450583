//! The bad-input matrix of the C ABI, generated from `include/ocean.h`.
//!
//! The test parses every prototype, struct and enum of the header (`matrix/header.rs`),
//! classifies every parameter by its type (`matrix/generate.rs`; a parameter or function it
//! cannot classify fails the test, so a new function is never skipped silently) and writes a
//! C11 program that, for each function, makes a base call with plausible arguments and then one
//! call per bad value of one parameter, the others as in the base call:
//!
//! - handles: NULL, a live handle of another kind, a destroyed handle, zeroed memory, `(void*)1`
//!   (NULL must give `OCEAN_STATUS_NULL_POINTER`, the others `OCEAN_STATUS_INVALID_HANDLE`);
//! - other pointers: NULL (`OCEAN_STATUS_NULL_POINTER`, or success where NULL is allowed) and,
//!   where the type's alignment exceeds 1, one byte off (`OCEAN_STATUS_MISALIGNED_POINTER`);
//! - lengths: 0, 1, `SIZE_MAX` and `SIZE_MAX/2+1`, never one beyond the real buffer unless its
//!   byte size overflows `PTRDIFF_MAX` (the library cannot know a caller's buffer size);
//! - floats: NaN, +-infinity, +-1e300 (+-`FLT_MAX` for `float`), -0, the smallest subnormal,
//!   `FLT_MAX` (and 1e30 for `float`); structs passed by value: the same for every member;
//! - structs passed by pointer: every float member NaN and 1e300 (`FLT_MAX` for `float`), every
//!   `uint32_t` member 0xFFFFFFFF, every flag 2, every `size_t` member 0 and `SIZE_MAX`; for an
//!   array followed by its count, also the last element's first float NaN;
//! - float input arrays: their first element NaN, +-infinity, `FLT_MAX`;
//! - `uint32_t` and enumerations: 0xFFFFFFFF, 1000 (and 0); flags: 2, 255; indices: 1000,
//!   0xFFFFFFFF, `SIZE_MAX`; strings: NULL, "", an unknown name, invalid UTF-8;
//! - progress callbacks: one going on (success if the base succeeded) and one cancelling
//!   (`OCEAN_STATUS_CANCELLED` if the base succeeded); `user`: NULL (the base's status);
//! - the error order: every variant again with the first handle destroyed
//!   (`OCEAN_STATUS_INVALID_HANDLE` whatever else is wrong), and every count and value variant
//!   again with each pointer NULL that is refused on its own (`OCEAN_STATUS_NULL_POINTER`).
//!
//! A length above `PTRDIFF_MAX` must give `OCEAN_STATUS_LENGTH_OVERFLOW` (counts come before the
//! mismatch of a length with a size), and a length of 1 where the documentation promises
//! `OCEAN_STATUS_LENGTH_MISMATCH` for any length but one (not 1) must give it when the base call
//! succeeds. Every call must return (a crash or a hang of more than
//! 30 s is a failure; the program is then rerun from the next variant) with a known status other
//! than `OCEAN_STATUS_PANIC`; a failure must leave a message starting with the function's name
//! and every output buffer untouched; a success must clear the message (one is set before every
//! call), write no output beyond the length its Safety section gives it, and leave every float it could have
//! written finite (+INFINITY where the member's documentation allows `INFINITY`). No call may
//! change a const input, or the memory passed as a foreign handle. Destroy functions are given
//! the same bad handles: NULL leaves the message alone, misuse is described there, and neither
//! frees the handle misused. The few functions that return no status must leave the message
//! alone.
//!
//! Not covered: the GPU handle kinds (`OceanGpuContext`, `OceanRenderer`, `OceanSaoGpu`) and
//! every function taking one (see `matrix::generate::GPU_KINDS`). The matrix makes thousands of
//! calls and CI's adapter may be a slow software rasteriser; `tests/c/test_gpu.c` covers their
//! error paths. Nor are two bad pointers together, or a bad count with a bad value (only the
//! precedence of handles and of pointers is checked), nor a length that fits in `PTRDIFF_MAX`
//! but not in the buffer (none of the lengths above falls there: the count is printed).
#![cfg(unix)]

mod c_build;
mod matrix;

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use matrix::generate::{Program, generate};
use matrix::header::Header;

/// Longest the whole matrix may run, all reruns together.
const DEADLINE: Duration = Duration::from_secs(600);
/// Most reruns after crashes and hangs before the test gives up.
const MAX_RERUNS: usize = 50;

fn header_and_harness() -> (Header, String) {
    let root = c_build::workspace_root();
    let text = std::fs::read_to_string(root.join("include/ocean.h")).expect("read include/ocean.h");
    let header =
        Header::parse(&text).unwrap_or_else(|e| panic!("include/ocean.h cannot be parsed: {e}"));
    let harness = std::fs::read_to_string(root.join("tests/c/matrix_harness.h"))
        .expect("read tests/c/matrix_harness.h");
    (header, harness)
}

fn program() -> Program {
    let (header, harness) = header_and_harness();
    let program = generate(&header, &harness)
        .unwrap_or_else(|e| panic!("the matrix cannot be generated from include/ocean.h:\n{e}"));
    assert_eq!(
        program.functions + program.gpu_skipped.len(),
        header.functions.len(),
        "every function of the header is exercised or skipped as a GPU function"
    );
    program
}

/// One run of the program from variant `start`: its stdout and exit code (None: killed).
fn run_from(exe: &Path, start: u64, deadline: Instant) -> (String, Option<i32>) {
    let mut child = Command::new(exe)
        .arg(start.to_string())
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot run {}: {e}", exe.display()));
    let mut stdout = child.stdout.take().expect("piped stdout");
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout.read_to_string(&mut s);
        s
    });
    let code = loop {
        if let Some(status) = child.try_wait().expect("wait for the matrix") {
            break status.code();
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    (reader.join().expect("stdout reader"), code)
}

#[test]
fn bad_input_matrix_generated_from_the_header() {
    let program = program();
    let root = c_build::workspace_root();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("c_matrix");
    std::fs::create_dir_all(&dir).expect("create the output directory");
    let source = dir.join("c_matrix.c");
    std::fs::write(&source, &program.source).expect("write the generated program");
    let exe = dir.join("c_matrix");
    let mut cc = Command::new(c_build::compiler("CC", "cc"));
    cc.arg("-std=c11")
        .args(c_build::WARNINGS)
        .arg(c_build::FULL_LIBRARY)
        .arg("-g")
        .arg("-I")
        .arg(root.join("include"))
        .arg("-I")
        .arg(root.join("tests/c"))
        .arg(&source)
        .arg(c_build::libocean(false))
        .args(c_build::NATIVE_STATIC_LIBS)
        .arg("-o")
        .arg(&exe);
    c_build::run(cc, "compile the generated matrix");

    let started = Instant::now();
    let deadline = started + DEADLINE;
    let mut start = 0u64;
    let mut failures: Vec<String> = Vec::new();
    let mut base_failures = Vec::new();
    let mut summary = None;
    for _ in 0..=MAX_RERUNS {
        let (out, code) = run_from(&exe, start, deadline);
        for line in out.lines() {
            if line.starts_with("FAIL ") {
                failures.push(line.to_owned());
            } else if line.starts_with("BASE ") {
                base_failures.push(line.to_owned());
            }
        }
        // A crash or hang names its variant id: count it as a failure, go on after it.
        let stopped = out
            .lines()
            .find(|l| l.starts_with("CRASH ") || l.starts_with("HANG "));
        if let Some(line) = stopped {
            failures.push(line.to_owned());
            let id: u64 = line
                .split_whitespace()
                .nth(1)
                .and_then(|s| s.parse().ok())
                .unwrap_or_else(|| panic!("no variant id in {line:?}"));
            start = id + 1;
            continue;
        }
        match code {
            Some(0 | 1) => {}
            Some(c) => panic!("the matrix exited with {c} after:\n{out}"),
            None => panic!("the matrix did not finish within {DEADLINE:?}; it printed:\n{out}"),
        }
        summary = Some(out);
        break;
    }
    let out = summary.unwrap_or_else(|| panic!("more than {MAX_RERUNS} crashes or hangs"));
    let field = |line: &str, word: &str| -> u64 {
        let head = &line[..line
            .find(word)
            .unwrap_or_else(|| panic!("{word:?} in {line:?}"))];
        head.rsplit(|c: char| !c.is_ascii_digit())
            .find(|s| !s.is_empty())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("no number before {word:?} in {line:?}"))
    };
    let counts = out
        .lines()
        .find(|l| l.starts_with("c_matrix: ") && l.contains(" functions, "))
        .unwrap_or_else(|| panic!("the matrix printed no summary:\n{out}"));
    let details = out
        .lines()
        .find(|l| l.starts_with("c_matrix: next id "))
        .unwrap_or_else(|| panic!("the matrix printed no details:\n{out}"));
    let functions = field(counts, " functions");
    // Every variant id is one call, made in exactly one of the runs.
    let calls = field(details, "; library");
    assert_eq!(functions, program.functions as u64, "{counts}");
    assert!(
        details.contains(&format!("library {}", env!("CARGO_PKG_VERSION"))),
        "the matrix linked a library of another version: {details}"
    );
    println!(
        "c_matrix: {functions} functions, {calls} calls, {} failures",
        failures.len()
    );
    println!("{details}");
    println!(
        "c_matrix: {} variants generated; structs without a default filled with zeros: {:?}; \
         {:.1} s",
        program.variants,
        program.zeroed_structs,
        started.elapsed().as_secs_f64()
    );
    for line in &base_failures {
        println!("{line}");
    }
    for line in &failures {
        println!("{line}");
    }
    assert!(calls > 1000, "suspiciously few calls: {details}");
    assert!(
        failures.is_empty(),
        "c_matrix: {} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// A prototype the generator has no role for fails generation, naming the function: new
/// functions are never skipped silently.
#[test]
fn an_unknown_parameter_type_fails_generation() {
    let (mut header, harness) = header_and_harness();
    let text = "typedef struct OceanNew { double x; } OceanNew;\n\
                OceanStatus ocean_new_function(const double **weird);\n";
    let extra = Header::parse(text).expect("parse the extra declarations");
    header.functions.extend(extra.functions);
    let err = generate(&header, &harness)
        .err()
        .expect("generation must fail for a parameter it cannot classify");
    assert!(
        err.contains("ocean_new_function") && err.contains("weird"),
        "{err}"
    );
}

/// A new handle kind without a maker in the harness fails generation.
#[test]
fn an_unknown_handle_kind_fails_generation() {
    let (mut header, harness) = header_and_harness();
    header.opaque.push("OceanNewKind".into());
    let err = generate(&header, &harness)
        .err()
        .expect("generation must fail for a handle kind the harness cannot make");
    assert!(err.contains("OceanNewKind"), "{err}");
}

/// No struct of the header has padding the compiler inserts unseen: each one's size is the sum
/// of its members' sizes, so a C or C++ caller that fills a struct member by member (or
/// compares two with `memcmp`) never meets uninitialised bytes, and a field added later cannot
/// land in a hole by accident. Checked by the C compiler itself (`_Static_assert` on `sizeof`),
/// for every struct the parser finds in `include/ocean.h`, GPU ones included.
#[test]
fn no_struct_of_the_header_has_implicit_padding() {
    let (header, _) = header_and_harness();
    assert!(
        header.structs.len() > 30,
        "only {} structs parsed",
        header.structs.len()
    );
    let mut source = String::from("#include <ocean.h>\n\n");
    for s in &header.structs {
        let sum = s
            .members
            .iter()
            .map(|m| format!("sizeof(((struct {} *)0)->{})", s.name, m.name))
            .collect::<Vec<_>>()
            .join(" + ");
        source.push_str(&format!(
            "_Static_assert(sizeof(struct {0}) == {sum}, \"{0} has implicit padding\");\n",
            s.name
        ));
    }
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("c_layout");
    std::fs::create_dir_all(&dir).expect("create the output directory");
    let path = dir.join("layout.c");
    std::fs::write(&path, source).expect("write the layout check");
    let mut cc = Command::new(c_build::compiler("CC", "cc"));
    cc.arg("-std=c11")
        .args(c_build::WARNINGS)
        .arg(c_build::FULL_LIBRARY)
        .arg("-fsyntax-only")
        .arg("-I")
        .arg(c_build::workspace_root().join("include"))
        .arg(&path);
    c_build::run(cc, "the layout check of include/ocean.h");
}
