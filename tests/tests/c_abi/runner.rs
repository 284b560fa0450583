//! Compiling, linking and running the C and C++ test programs of `c_abi.rs`, plain or under the
//! checker `OCEAN_SANITIZE` selects.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::c_build::{
    FULL_LIBRARY, NATIVE_STATIC_LIBS, WARNINGS, libocean, run, soname, workspace_root,
};

/// The checker `OCEAN_SANITIZE` selects (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sanitize {
    None,
    Address,
    Thread,
    Memcheck,
}

impl Sanitize {
    fn from_env() -> Self {
        match std::env::var("OCEAN_SANITIZE").as_deref() {
            Err(_) | Ok("") => Self::None,
            Ok("address") => Self::Address,
            Ok("thread") => Self::Thread,
            Ok("memcheck") => Self::Memcheck,
            Ok(other) => panic!(
                "OCEAN_SANITIZE={other:?}: expected `address`, `thread` or `memcheck` (or unset)"
            ),
        }
    }

    fn dir_name(self) -> &'static str {
        match self {
            Self::None => "plain",
            Self::Address => "address",
            Self::Thread => "thread",
            Self::Memcheck => "memcheck",
        }
    }

    /// Compiler flags besides the warnings.
    fn cflags(self) -> &'static [&'static str] {
        match self {
            Self::None | Self::Memcheck => &[],
            Self::Address => &[
                "-fsanitize=address,undefined",
                "-fno-omit-frame-pointer",
                "-fno-sanitize-recover=all",
            ],
            Self::Thread => &["-fsanitize=thread", "-fno-omit-frame-pointer"],
        }
    }

    /// What a report of this checker starts with, in the program's stderr: a program that exits
    /// 0 despite one (an option overridden from the environment) still fails.
    fn report_markers(self) -> &'static [&'static str] {
        match self {
            Self::None => &[],
            Self::Address => &[
                "ERROR: AddressSanitizer",
                "ERROR: LeakSanitizer",
                "runtime error:",
            ],
            Self::Thread => &["WARNING: ThreadSanitizer"],
            Self::Memcheck => &[],
        }
    }
}

/// Sets `var` to `ours` followed by the caller's own value, if any: later options win, so a
/// developer can still add or override one (`ASAN_OPTIONS=verbosity=1 ...`).
fn options_env(cmd: &mut Command, var: &str, ours: &str) {
    let mut value = OsString::from(ours);
    if let Some(theirs) = std::env::var_os(var).filter(|v| !v.is_empty()) {
        value.push(":");
        value.push(theirs);
    }
    cmd.env(var, value);
}

/// The software Vulkan and GL drivers that LeakSanitizer must find still loaded at exit to name
/// their leaks (tests/lsan.supp): the Vulkan loader and EGL unload them when the library's GPU
/// context is destroyed, before LSan looks, and a leak in an unloaded module has no name that
/// a suppression could match. `c_compiler -print-file-name` finds them where the system keeps
/// its libraries (Debian: /usr/lib/x86_64-linux-gnu/libvulkan_lvp.so and
/// /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so); those not found are left out.
fn resident_drivers(c_compiler: &OsString) -> Vec<PathBuf> {
    ["libvulkan_lvp.so", "dri/swrast_dri.so"]
        .into_iter()
        .filter_map(|name| {
            let out = Command::new(c_compiler)
                .arg(format!("-print-file-name={name}"))
                .output()
                .ok()?;
            let path = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
            // A name it cannot find comes back as it was given, relative.
            if path.is_absolute() {
                path.canonicalize().ok()
            } else {
                None
            }
        })
        .collect()
}

/// What a program needs besides its source.
#[derive(Default)]
pub(crate) struct Extras<'a> {
    /// Environment variables for the program.
    pub(crate) env: &'a [(&'a str, &'a Path)],
    /// It creates a GPU context (Mesa's drivers are loaded into it).
    pub(crate) gpu: bool,
    /// It starts threads of its own (`-pthread`).
    pub(crate) threads: bool,
}

/// Compiles `source` with `compiler` and `std`, links it with libocean.a, runs it and checks its
/// summary line.
pub(crate) fn build_and_run(compiler: OsString, std_flag: &str, source: &str, exe_name: &str) {
    build_and_run_with(compiler, std_flag, source, exe_name, &Extras::default());
}

/// [`build_and_run`] with [`Extras`], under the checker `OCEAN_SANITIZE` selects; returns the
/// program's stdout.
pub(crate) fn build_and_run_with(
    compiler: OsString,
    std_flag: &str,
    source: &str,
    exe_name: &str,
    extras: &Extras,
) -> String {
    let root = workspace_root();
    let sanitize = Sanitize::from_env();
    let out_dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c_abi")
        .join(sanitize.dir_name());
    std::fs::create_dir_all(&out_dir).expect("create the output directory");
    let exe = out_dir.join(exe_name);

    let mut cc = Command::new(&compiler);
    cc.arg(std_flag)
        .args(WARNINGS)
        .arg("-g")
        .args(sanitize.cflags())
        .args(extras.threads.then_some("-pthread"))
        .arg(FULL_LIBRARY)
        .arg("-I")
        .arg(root.join("include"))
        .arg(root.join(source));
    if sanitize == Sanitize::Thread {
        // The program records the cdylib's SONAME (ocean-ffi/build.rs) and finds it at run
        // time through a link of that name beside it; the library brings its own system
        // libraries, but the programs' <math.h> needs libm.
        // The tests run in parallel and share the directory: make the link under a name of
        // this program's own, then rename it over the shared name (atomic).
        let shared = libocean(true);
        let link = out_dir.join(soname());
        let own = out_dir.join(format!(".{}.{exe_name}", soname()));
        let _ = std::fs::remove_file(&own);
        std::os::unix::fs::symlink(&shared, &own).expect("link the SONAME to the cdylib");
        std::fs::rename(&own, &link).expect("move the SONAME link into place");
        cc.arg(shared)
            .arg(format!("-Wl,-rpath,{}", out_dir.display()))
            .arg("-lm");
    } else {
        cc.arg(libocean(false)).args(NATIVE_STATIC_LIBS);
    }
    cc.arg("-o").arg(&exe);
    run(cc, &format!("compile {source}"));

    let mut program = match sanitize {
        Sanitize::Memcheck => {
            let mut vg = Command::new("valgrind");
            vg.args([
                "--error-exitcode=1",
                "--leak-check=full",
                "--errors-for-leak-kinds=definite,indirect",
                "--show-leak-kinds=definite,indirect",
                // Names the frames of drivers unloaded before exit, for the suppressions.
                "--keep-debuginfo=yes",
                "--num-callers=40",
            ])
            .arg(suppressions_arg(&root.join("tests/valgrind.supp")))
            .arg(&exe);
            vg
        }
        _ => Command::new(&exe),
    };
    program.envs(extras.env.iter().copied());
    match sanitize {
        Sanitize::None | Sanitize::Memcheck => {}
        Sanitize::Address => {
            let mut asan = String::from(
                "detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:\
                 check_initialization_order=1:strict_init_order=1",
            );
            if extras.gpu {
                let drivers = resident_drivers(&compiler);
                if !drivers.is_empty() {
                    // Preloaded libraries come before the ASan runtime in the link order, which
                    // ASan refuses unless told; they define no allocator, so its interception
                    // is intact.
                    asan.push_str(":verify_asan_link_order=0");
                    program.env("LD_PRELOAD", join_paths(&drivers, " "));
                }
            }
            options_env(&mut program, "ASAN_OPTIONS", &asan);
            options_env(
                &mut program,
                "UBSAN_OPTIONS",
                "print_stacktrace=1:halt_on_error=1",
            );
            options_env(
                &mut program,
                "LSAN_OPTIONS",
                &format!(
                    "print_suppressions=1:suppressions={}",
                    root.join("tests/lsan.supp").display()
                ),
            );
        }
        Sanitize::Thread => options_env(
            &mut program,
            "TSAN_OPTIONS",
            "halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1",
        ),
    }
    let (stdout, stderr) = run(
        program,
        &format!("run {exe_name} ({})", sanitize.dir_name()),
    );
    for marker in sanitize.report_markers() {
        assert!(
            !stderr.contains(marker),
            "{exe_name}: a {} report despite exit status 0:\n{stderr}",
            sanitize.dir_name()
        );
    }
    if sanitize == Sanitize::Memcheck {
        assert!(
            stderr.contains("ERROR SUMMARY: 0 errors"),
            "{exe_name}: valgrind reported errors:\n{stderr}"
        );
    }
    // The programs print "<file>: library <version>, <N> checks, <F> failures; ...". Require
    // the line, N > 0 and F = 0, so an empty or truncated run cannot pass.
    let summary = stdout
        .lines()
        .find(|l| l.contains(" checks, "))
        .unwrap_or_else(|| panic!("{exe_name} printed no summary:\n{stdout}"));
    let number_before = |word: &str| -> u64 {
        let head = &summary[..summary.find(word).expect("summary word")];
        head.rsplit(|c: char| !c.is_ascii_digit())
            .find(|s| !s.is_empty())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("no number before {word:?} in {summary:?}"))
    };
    assert!(number_before(" checks") > 0, "{summary}");
    assert_eq!(number_before(" failures"), 0, "{summary}");
    assert!(
        summary.contains(&format!("library {}", env!("CARGO_PKG_VERSION"))),
        "the program linked a library of another version: {summary}"
    );
    // A passing program's executable is no longer needed, and each one carries the static
    // library's debug information (about 170 MB): remove it so the suites under every checker
    // do not fill the disk. A failing one stays for the developer to run again.
    let _ = std::fs::remove_file(&exe);
    stdout
}

/// `--suppressions=<path>` for valgrind.
fn suppressions_arg(path: &Path) -> OsString {
    let mut arg = OsString::from("--suppressions=");
    arg.push(path);
    arg
}

fn join_paths(paths: &[PathBuf], sep: &str) -> OsString {
    let mut joined = OsString::new();
    for (i, p) in paths.iter().enumerate() {
        if i > 0 {
            joined.push(sep);
        }
        joined.push(p);
    }
    joined
}
