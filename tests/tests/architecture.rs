//! The shape of the code, checked: no import cycle between the modules of one crate, and no
//! source file over 800 lines unless its head says why.
//!
//! Modules: each `.rs` file under a crate's `src/` is a module (`a/b.rs` is `a::b`, `mod.rs`
//! and `lib.rs` name their folder). Module `m` depends on module `t` where the code of `m`
//! (comments, string literals and everything after the first `#[cfg(test)]` left out) names a
//! path `crate::t::...` or `super::...` that resolves to `t`; a module and its own ancestors or
//! descendants are one unit and never count. A cycle is a strongly connected component of more
//! than one module: lower modules must not import higher ones (ARCHITECTURE.md).
//!
//! Both checks ratchet: [`KNOWN_CYCLES`] and [`KNOWN_LONG`] list what is still to be fixed, and
//! the test fails on anything new and on any listed entry that no longer holds, so each fix
//! removes its entry.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Import cycles still to be broken: (crate, the modules of one cycle, sorted).
const KNOWN_CYCLES: &[(&str, &[&str])] = &[];

/// Files over [`MAX_LINES`] without a stated reason, still to be split.
const KNOWN_LONG: &[&str] = &[];

/// Longest a source file may be without a reason at its head.
const MAX_LINES: usize = 800;

/// What a long file's head (its first 30 lines) says to be allowed: the words after it say why.
const LONG_REASON: &str = "Long file:";

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests crate is inside the workspace")
        .to_path_buf()
}

/// The workspace's crates with sources: every `ocean-*` folder with a `src/`, and `tests`.
fn crates(root: &Path) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name.starts_with("ocean-") || name == "tests") && p.join("src").is_dir()
        })
        .collect();
    out.sort();
    out
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module path of a file under `src` ("" for the crate root).
fn module_of(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("lib" | "main" | "mod")
    ) {
        parts.pop();
    }
    parts.join("::")
}

/// The code of a file: before its first test module, without comments and string literals.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap();
    let mut out = String::with_capacity(text.len());
    for line in text.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("//") {
            continue;
        }
        // Drop string literals (a path inside a message is no dependency).
        let mut in_str = false;
        let mut escaped = false;
        for c in line.chars() {
            if in_str {
                if escaped {
                    escaped = false;
                } else if c == '\\' {
                    escaped = true;
                } else if c == '"' {
                    in_str = false;
                }
            } else if c == '"' {
                in_str = true;
            } else {
                out.push(c);
            }
        }
        out.push('\n');
    }
    out
}

/// The identifier segments of each `prefix::a::b` path in `code`.
fn paths_after<'a>(code: &'a str, prefix: &str) -> Vec<Vec<&'a str>> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find(prefix) {
        let head = &rest[..at];
        let before = head.chars().next_back();
        let after = &rest[at + prefix.len()..];
        rest = after;
        // Only where a path starts: not inside a name, nor after another segment (the second
        // `super::` of `super::super::`).
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') || head.ends_with("::") {
            continue;
        }
        let mut segs = Vec::new();
        let mut s = after;
        loop {
            let len = s
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(s.len());
            if len == 0 {
                break;
            }
            segs.push(&s[..len]);
            s = &s[len..];
            match s.strip_prefix("::") {
                Some(t) => s = t,
                None => break,
            }
        }
        out.push(segs);
    }
    out
}

fn related(a: &str, b: &str) -> bool {
    a == b
        || a.is_empty()
        || b.is_empty()
        || a.starts_with(&format!("{b}::"))
        || b.starts_with(&format!("{a}::"))
}

/// Module → the modules it depends on, with one line of code naming each.
type Graph = BTreeMap<String, BTreeMap<String, String>>;

fn graph(krate: &Path) -> Graph {
    let src = krate.join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let modules: BTreeMap<String, PathBuf> = files
        .iter()
        .map(|f| (module_of(&src, f), f.clone()))
        .collect();
    let resolve = |segs: &[&str]| -> Option<String> {
        (1..=segs.len())
            .rev()
            .map(|k| segs[..k].join("::"))
            .find(|m| modules.contains_key(m))
    };
    let mut g = Graph::new();
    for (m, file) in &modules {
        let code = code(&std::fs::read_to_string(file).unwrap());
        let deps = g.entry(m.clone()).or_default();
        let parent = m.rsplit_once("::").map_or("", |(p, _)| p);
        let mut targets: Vec<(String, String)> = Vec::new();
        for segs in paths_after(&code, "crate::") {
            if let Some(t) = resolve(&segs) {
                targets.push((t, format!("crate::{}", segs.join("::"))));
            }
        }
        for segs in paths_after(&code, "super::") {
            // `super::super::x`: one more level up for each further `super`.
            let ups = segs.iter().take_while(|s| **s == "super").count();
            let mut full: Vec<&str> = parent.split("::").filter(|s| !s.is_empty()).collect();
            if ups > full.len() {
                continue;
            }
            full.truncate(full.len() - ups);
            full.extend(&segs[ups..]);
            if let Some(t) = resolve(&full) {
                targets.push((t, format!("super::{}", segs.join("::"))));
            }
        }
        for (t, how) in targets {
            if !related(m, &t) {
                deps.entry(t).or_insert(how);
            }
        }
    }
    g
}

/// Strongly connected components of more than one module (Tarjan), each sorted.
fn cycles(g: &Graph) -> Vec<Vec<String>> {
    struct State<'g> {
        g: &'g Graph,
        index: BTreeMap<&'g str, usize>,
        low: BTreeMap<&'g str, usize>,
        stack: Vec<&'g str>,
        on: BTreeSet<&'g str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'g>(s: &mut State<'g>, v: &'g str) {
        let i = s.index.len();
        s.index.insert(v, i);
        s.low.insert(v, i);
        s.stack.push(v);
        s.on.insert(v);
        for w in s.g[v].keys() {
            let w = w.as_str();
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if s.on.contains(w) {
                let iw = s.index[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on.remove(w);
                comp.push(w.to_owned());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                s.out.push(comp);
            }
        }
    }
    let mut s = State {
        g,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in g.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out.sort();
    s.out
}

#[test]
fn no_module_imports_a_higher_one() {
    let root = workspace_root();
    let mut found = BTreeSet::new();
    let mut report = String::new();
    for krate in crates(&root) {
        let name = krate.file_name().unwrap().to_string_lossy().into_owned();
        let g = graph(&krate);
        for comp in cycles(&g) {
            let known = KNOWN_CYCLES
                .iter()
                .any(|(c, ms)| *c == name && ms.iter().eq(comp.iter()));
            if !known {
                report.push_str(&format!("{name}: a cycle through {comp:?}:\n"));
                for m in &comp {
                    for (t, how) in &g[m] {
                        if comp.contains(t) {
                            report.push_str(&format!("    {m} -> {t} ({how})\n"));
                        }
                    }
                }
            }
            found.insert((name.clone(), comp));
        }
    }
    for (c, ms) in KNOWN_CYCLES {
        let comp: Vec<String> = ms.iter().map(|m| (*m).to_owned()).collect();
        if !found.contains(&((*c).to_owned(), comp)) {
            report.push_str(&format!(
                "{c}: {ms:?} is no longer a cycle: remove it from KNOWN_CYCLES\n"
            ));
        }
    }
    assert!(report.is_empty(), "\n{report}");
}

#[test]
fn long_files_say_why() {
    let root = workspace_root();
    let mut report = String::new();
    let mut long = BTreeSet::new();
    for krate in crates(&root) {
        let mut files = Vec::new();
        for dir in ["src", "tests", "benches"] {
            if krate.join(dir).is_dir() {
                rust_files(&krate.join(dir), &mut files);
            }
        }
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            let lines = text.lines().count();
            let rel = file
                .strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .into_owned();
            let reason = text.lines().take(30).any(|l| l.contains(LONG_REASON));
            if lines > MAX_LINES && !reason {
                if !KNOWN_LONG.contains(&rel.as_str()) {
                    report.push_str(&format!(
                        "{rel}: {lines} lines, over {MAX_LINES}, and its head gives no \
                         `{LONG_REASON}` reason: split it along its seams\n"
                    ));
                }
                long.insert(rel);
            }
        }
    }
    for k in KNOWN_LONG {
        if !long.contains(*k) {
            report.push_str(&format!(
                "{k} is no longer long without a reason: remove it from KNOWN_LONG\n"
            ));
        }
    }
    assert!(report.is_empty(), "\n{report}");
}

/// The checker itself, on a made-up crate: a cycle through `super::` and `crate::` paths is
/// found, a path in a comment, a string or a test module is not a dependency, and a module's
/// own descendants never count.
#[test]
fn the_cycle_check_sees_what_it_should() {
    let dir = std::env::temp_dir().join(format!("ocean-architecture-{}", std::process::id()));
    let src = dir.join("src");
    std::fs::create_dir_all(src.join("a")).unwrap();
    let write = |p: &str, t: &str| std::fs::write(src.join(p), t).unwrap();
    write("lib.rs", "mod a;\nmod b;\nmod c;\nuse crate::a::x;\n");
    write(
        "a/mod.rs",
        "mod inner;\nuse crate::b::Y;\nuse self::inner::Z;\n",
    );
    write("a/inner.rs", "use super::super::c::W;\n");
    write(
        "b.rs",
        "// crate::c in a comment\nfn f() { let _ = \"crate::c\"; }\n",
    );
    write(
        "c.rs",
        "use crate::a::inner::Z;\n#[cfg(test)]\nmod tests { use crate::b::Y; }\n",
    );
    let g = graph(&dir);
    assert_eq!(g["a"].keys().collect::<Vec<_>>(), ["b"], "{g:?}");
    assert!(g["b"].is_empty(), "{g:?}");
    assert_eq!(
        cycles(&g),
        vec![vec!["a::inner".to_owned(), "c".to_owned()]]
    );
    write("c.rs", "pub struct W;\n");
    assert!(cycles(&graph(&dir)).is_empty());
    std::fs::remove_dir_all(&dir).unwrap();
}
