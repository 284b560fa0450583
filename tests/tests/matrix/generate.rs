//! Generates the bad-input matrix, a C11 program, from the parsed header (see
//! `tests/tests/c_matrix.rs` for what it checks and `tests/c/matrix_harness.h` for the fixed
//! half it includes).
//!
//! Every parameter is classified by its C type (and, for `size_t` and `void *`, its name) into a
//! [`Role`]; the role gives the base value and the bad values. A parameter or function that fits
//! no role is an error, so a new kind of argument can never be skipped silently.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use super::classify::*;
use super::header::{Base, Function, Header};

/// The stage of the header's error order a variant's bad value belongs to.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Stage {
    /// (1) a handle.
    Handle,
    /// (2) another pointer: NULL or misaligned.
    Pointer,
    /// (3)-(5) a count, a value, or the work it leads to.
    Value,
}

/// What a variant may return.
#[derive(Clone)]
pub(super) enum Expect {
    Any,
    /// One of these statuses (names of `OceanStatus` values).
    Only(Vec<&'static str>),
    /// When the base call succeeded, exactly this status.
    IfBaseOk(&'static str),
    /// The base call's status.
    SameAsBase,
    /// OCEAN_STATUS_NULL_POINTER if parameter i alone NULL gave it (a required pointer).
    IfNullRefused(usize),
}

#[derive(Clone)]
pub(super) struct Variant {
    pub(super) param: String,
    pub(super) value: String,
    /// C statements mutating `a` (the arguments) or the scratch buffers after the base.
    pub(super) code: String,
    pub(super) expect: Expect,
    /// A length value: run only if `matrix_length_ok` allows it.
    pub(super) length: Option<String>,
    /// The parameter it changes (None: several).
    pub(super) index: Option<usize>,
    pub(super) stage: Stage,
    /// Records whether this single NULL of parameter i is refused (for [`Expect::IfNullRefused`]).
    pub(super) mark_null: Option<usize>,
}

/// The generated program and what it covers.
pub struct Program {
    pub source: String,
    /// Functions exercised (status-returning, destroy and plain).
    pub functions: usize,
    /// Functions skipped because they take or make a GPU handle.
    pub gpu_skipped: Vec<String>,
    /// Variants per role, for the report.
    pub variants: usize,
    /// Structs filled with zeros (no `_default` function, no `plausible_` filler).
    pub zeroed_structs: BTreeSet<String>,
}

pub(super) struct Gen<'a> {
    pub(super) h: &'a Header,
    pub(super) harness: &'a str,
    /// CPU handle kinds, in header order.
    pub(super) kinds: Vec<String>,
    /// Kinds a function mutates (a non-const handle): remade before each such function.
    pub(super) mutable: BTreeSet<String>,
    pub(super) structs_filled: BTreeSet<String>,
    pub(super) structs_checked: BTreeSet<String>,
    pub(super) zeroed: BTreeSet<String>,
    pub(super) out: String,
    pub(super) variants: usize,
}

pub(super) fn c_ident_ok(s: &str) -> bool {
    s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

impl Gen<'_> {
    pub(super) fn kind_index(&self, kind: &str) -> usize {
        self.kinds
            .iter()
            .position(|k| k == kind)
            .expect("kinds are collected first")
    }

    /// The `ocean_*_default(struct S *out)` function of a struct, if any.
    pub(super) fn default_fn(&self, s: &str) -> Option<&str> {
        self.h.functions.iter().find_map(|f| {
            let only_out = matches!(
                f.params.as_slice(),
                [p] if p.ty.stars == 1 && !p.ty.konst && p.ty.base == Base::Struct(s.into())
            );
            (f.name.ends_with("_default") && only_out && f.ret.base_name() == "OceanStatus")
                .then_some(f.name.as_str())
        })
    }

    /// Name of the C function filling `n` elements of struct `s` at `buf` (generated once).
    pub(super) fn filler(&mut self, s: &str) -> String {
        self.structs_filled.insert(s.to_owned());
        format!("fill_{s}")
    }

    pub(super) fn emit_fillers(&mut self) -> Result<String, String> {
        let mut c = String::new();
        for s in self.structs_filled.clone() {
            let how = if let Some(d) = self.default_fn(&s) {
                format!(
                    "if ({d}(&e) != OCEAN_STATUS_OK)\n        \
                     matrix_fail(\"{d} failed: %s\", ocean_last_error_message());"
                )
            } else if self.harness.contains(&format!("plausible_{s}(")) {
                format!("plausible_{s}(&e);")
            } else {
                self.zeroed.insert(s.clone());
                "/* no default and no plausible value: zeroed */".to_owned()
            };
            // Copied member by member into a zeroed struct: a struct the library wrote may
            // hold indeterminate padding, which the check that const inputs come back
            // unchanged would compare (memcheck reports it).
            let members: String = struct_leaves(self.h, &s)?
                .iter()
                .map(|l| format!("    z{p} = e{p};\n", p = l.path))
                .collect();
            let _ = write!(
                c,
                "static inline void fill_{s}(unsigned char *buf, size_t n)\n{{\n    \
                 {s} e, z;\n    size_t i;\n    memset(&e, 0, sizeof e);\n    \
                 memset(&z, 0, sizeof z);\n    {how}\n{members}    \
                 if (n > MATRIX_BUF / sizeof z)\n        n = MATRIX_BUF / sizeof z;\n    \
                 for (i = 0; i < n; i++)\n        memcpy(buf + i * sizeof z, &z, sizeof z);\n}}\n\n"
            );
        }
        Ok(c)
    }

    pub(super) fn checker(&mut self, s: &str) -> String {
        self.structs_checked.insert(s.to_owned());
        format!("finite_{s}")
    }

    pub(super) fn emit_checkers(&self) -> Result<String, String> {
        let mut c = String::new();
        for s in &self.structs_checked {
            let mut body = String::new();
            for leaf in struct_leaves(self.h, s)?
                .iter()
                .filter(|l| l.prim.is_float())
            {
                let _ = write!(
                    body,
                    "        if (!matrix_ok_value(e.{p}, {inf})) {{\n            \
                     matrix_nonfinite(name, i, \"{path}\", e.{p});\n            return;\n        }}\n",
                    p = &leaf.path[1..],
                    path = leaf.path,
                    inf = i32::from(leaf.infinity_ok),
                );
            }
            let _ = write!(
                c,
                "static inline void finite_{s}(const unsigned char *buf, size_t n, const char *name)\n\
                 {{\n    size_t i;\n    for (i = 0; i < n; i++) {{\n        {s} e;\n        \
                 memcpy(&e, buf + i * sizeof e, sizeof e);\n{body}    }}\n}}\n\n"
            );
        }
        Ok(c)
    }

    pub(super) fn has_float_leaves(&self, s: &str) -> Result<bool, String> {
        Ok(struct_leaves(self.h, s)?.iter().any(|l| l.prim.is_float()))
    }

    pub(super) fn run_destroy(&mut self, f: &Function, kind: &str) {
        let k = self.kind_index(kind);
        let fname = &f.name;
        let ty = f.params[0].ty.to_string();
        let n = &f.params[0].name;
        let mut c = format!(
            "/* void {fname}({ty} {n}) */\nstatic void run_{fname}(void)\n{{\n    \
             matrix_function(\"{fname}\");\n"
        );
        // (value label, handle expression, checks after the call)
        let cases: [(&str, String, String); 6] = [
            (
                "a live handle",
                format!("matrix_kinds_table[{k}].make()"),
                format!(
                    "        matrix_message_kept();\n        matrix_expect_alive({k}, h, 0);\n"
                ),
            ),
            (
                "NULL",
                "NULL".into(),
                "        matrix_message_kept();\n".into(),
            ),
            (
                "another kind",
                format!("matrix_other({k})"),
                format!(
                    "        matrix_message_set();\n        \
                     matrix_expect_alive(({k} + 1) % M.nkinds, h, 1);\n"
                ),
            ),
            (
                "destroyed",
                format!("matrix_dead({k})"),
                "        matrix_message_set();\n".into(),
            ),
            (
                "zeroed memory",
                "(void *)foreign_memory".into(),
                "        matrix_message_set();\n        matrix_foreign_untouched();\n".into(),
            ),
            (
                "(void*)1",
                "(void *)(uintptr_t)1".into(),
                "        matrix_message_set();\n".into(),
            ),
        ];
        for (i, (label, expr, after)) in cases.iter().enumerate() {
            let param = if i == 0 { "(base)" } else { n.as_str() };
            let _ = write!(
                c,
                "    if (matrix_begin(\"{param}\", \"{label}\")) {{\n        void *h = {expr};\n        \
                 matrix_pre_plain();\n        {fname}(({ty})h);\n        matrix_post_plain();\n{after}    }}\n"
            );
        }
        c.push_str("}\n\n");
        self.variants += cases.len();
        self.out.push_str(&c);
    }

    pub(super) fn run_plain(&mut self, f: &Function, roles: &[Role]) {
        let fname = &f.name;
        let returns_string = f.ret.base_name() == "char";
        let mut c = format!(
            "/* {} {fname}(...) */\nstatic void run_{fname}(void)\n{{\n    matrix_function(\"{fname}\");\n",
            f.ret
        );
        // The base (every argument 0) and, per uint32_t argument, 1000 and 0xFFFFFFFF.
        let mut cases = vec![("(base)".to_owned(), "0".to_owned(), vec!["0"; roles.len()])];
        for (i, p) in f.params.iter().enumerate() {
            for value in ["1000", "0xFFFFFFFFu"] {
                let mut args = vec!["0"; roles.len()];
                args[i] = value;
                cases.push((p.name.clone(), value.to_owned(), args));
            }
        }
        for (param, value, args) in &cases {
            let check = if returns_string {
                "        if (!r)\n            matrix_fail(\"returned NULL\");\n"
            } else {
                "        (void)r;\n"
            };
            let _ = write!(
                c,
                "    if (matrix_begin(\"{param}\", \"{value}\")) {{\n        {ret} r;\n        \
                 matrix_pre_plain();\n        r = {fname}({args});\n        matrix_post_plain();\n\
                 {check}        matrix_message_kept();\n    }}\n",
                ret = f.ret,
                args = args.join(", "),
            );
        }
        c.push_str("}\n\n");
        self.variants += cases.len();
        self.out.push_str(&c);
    }
}

/// Generates the program for `h`; `harness` is the text of `tests/c/matrix_harness.h` (its
/// `plausible_` fillers and callbacks are used where it defines them).
pub fn generate(h: &Header, harness: &str) -> Result<Program, String> {
    // Statuses, dense from 0, so the program can name them.
    let status = h.enum_def("OceanStatus").ok_or("no enum OceanStatus")?;
    for (i, (name, v)) in status.values.iter().enumerate() {
        if *v != i as u64 {
            return Err(format!(
                "OceanStatus {name} = {v} breaks the dense numbering"
            ));
        }
    }
    let mut errors = Vec::new();
    for (f, p, _) in OVERRIDES {
        if !h.functions.iter().any(|x| x.name == *f) {
            errors.push(format!(
                "override for {f}.{p}: no such function in the header"
            ));
        }
    }
    let kinds: Vec<String> = h
        .opaque
        .iter()
        .filter(|k| !GPU_KINDS.contains(&k.as_str()))
        .cloned()
        .collect();
    for k in &kinds {
        if !harness.contains(&format!("make_{k}(void)")) {
            errors.push(format!(
                "handle kind {k}: tests/c/matrix_harness.h has no make_{k}() (a new kind: teach \
                 the harness to make one)"
            ));
        }
    }
    let mut g = Gen {
        h,
        harness,
        kinds: kinds.clone(),
        mutable: BTreeSet::new(),
        structs_filled: BTreeSet::new(),
        structs_checked: BTreeSet::new(),
        zeroed: BTreeSet::new(),
        out: String::new(),
        variants: 0,
    };
    let mut gpu_skipped = Vec::new();
    let mut runs = Vec::new();
    let mut classes = Vec::new();
    for f in &h.functions {
        match classify_function(h, f) {
            Ok(class) => classes.push((f, class)),
            Err(e) => errors.push(e),
        }
    }
    // A query per kind: the first status-returning function whose only arguments are one handle
    // of the kind and one output; it tells a live handle from a dead one.
    let mut alive = Vec::new();
    for k in &kinds {
        let q = classes.iter().find(|(f, c)| match c {
            Class::Fallible(r) => {
                matches!(r.as_slice(), [Role::Handle { kind }, Role::OutArray { .. } | Role::OutStruct { .. }] if kind == k)
                    && f.params[1].ty.stars == 1
            }
            _ => false,
        });
        match q {
            Some((f, _)) => alive.push((
                f.name.clone(),
                f.params[0].ty.clone(),
                f.params[1].ty.pointee(),
            )),
            None => errors.push(format!(
                "handle kind {k}: no query function to tell it alive"
            )),
        }
    }
    if !errors.is_empty() {
        return Err(errors.join("\n"));
    }
    for (f, class) in &classes {
        let gpu = f
            .params
            .iter()
            .any(|p| GPU_KINDS.contains(&p.ty.base_name()));
        if gpu {
            gpu_skipped.push(f.name.clone());
            continue;
        }
        match class {
            Class::Fallible(roles) => g.run(f, roles)?,
            Class::Destroy { kind } => g.run_destroy(f, kind),
            Class::Plain(roles) => g.run_plain(f, roles),
        }
        runs.push(f.name.clone());
    }

    let mut src = String::new();
    src.push_str(
        "/* Generated by tests/tests/c_matrix.rs from include/ocean.h: do not edit. */\n\
         #define _POSIX_C_SOURCE 200809L\n#include \"ocean.h\"\n\n",
    );
    let _ = writeln!(
        src,
        "static const char *const matrix_status_names[] = {{\n{}}};\n#define MATRIX_STATUS_COUNT {}\n",
        status
            .values
            .iter()
            .map(|(n, _)| format!("    \"{n}\",\n"))
            .collect::<String>(),
        status.values.len()
    );
    src.push_str(
        "#include \"matrix_harness.h\"\n\n#define MATRIX_MAX(a, b) ((a) > (b) ? (a) : (b))\n\n",
    );
    let _ = writeln!(src, "/* CPU handle kinds, in header order. */");
    for (i, k) in kinds.iter().enumerate() {
        let destroy = h
            .functions
            .iter()
            .find(
                |f| matches!(classify_function(h, f), Ok(Class::Destroy { ref kind }) if kind == k),
            )
            .ok_or(format!("handle kind {k}: no destroy function"))?;
        let (query, handle_ty, out_ty) = &alive[i];
        let _ = write!(
            src,
            "static void destroy_{k}(void *h) {{ {d}((struct {k} *)h); }}\n\
             static int alive_{k}(const void *h)\n{{\n    {out_ty} out;\n    \
             return {query}(({handle_ty})h, &out) == OCEAN_STATUS_OK;\n}}\n",
            d = destroy.name,
        );
    }
    let _ = writeln!(
        src,
        "\nstatic const struct matrix_kind matrix_kinds_table[] = {{\n{}}};\n",
        kinds
            .iter()
            .map(|k| format!("    {{\"{k}\", make_{k}, destroy_{k}, alive_{k}}},\n"))
            .collect::<String>()
    );
    src.push_str(&g.emit_fillers()?);
    src.push_str(&g.emit_checkers()?);
    src.push_str(&g.out);
    let _ = write!(
        src,
        "int main(int argc, char **argv)\n{{\n    matrix_init(argc, argv);\n    \
         matrix_setup_kinds(matrix_kinds_table, {});\n{}    return matrix_summary(\"{}\");\n}}\n",
        kinds.len(),
        runs.iter()
            .map(|r| format!("    run_{r}();\n"))
            .collect::<String>(),
        gpu_skipped.join(", ")
    );
    Ok(Program {
        source: src,
        functions: runs.len(),
        gpu_skipped,
        variants: g.variants,
        zeroed_structs: g.zeroed,
    })
}
