//! The variants of one function of the bad-input matrix: the argument struct, the base call with
//! its checks, and every bad value its parameters' roles give, in the header's error order. One
//! function ([`Gen::run`]) walks the parameters once, since each role's bad values depend on the
//! lengths and outputs found beside it.

use std::fmt::Write as _;

use super::classify::*;
use super::generate::{Expect, Gen, Stage, Variant, c_ident_ok};
use super::header::Function;

impl Gen<'_> {
    pub(super) fn run(&mut self, f: &Function, roles: &[Role]) -> Result<(), String> {
        if f.params.len() > 12 {
            return Err(format!("{}: more parameters than scratch slots", f.name));
        }
        let fname = &f.name;
        let overrides: Vec<_> = OVERRIDES.iter().filter(|o| o.0 == *fname).collect();
        for o in &overrides {
            if !f.params.iter().any(|p| p.name == o.1) {
                return Err(format!("override for {fname}: no parameter `{}`", o.1));
            }
        }
        let over = |p: &str| overrides.iter().find(|o| o.1 == p).map(|o| o.2);
        // The lengths the documentation holds to an exact value (LENGTH_MISMATCH otherwise).
        let exact = exact_lengths(f);

        // The argument struct, the base, the call with its checks.
        let mut fields = String::new();
        let mut base = String::new();
        let mut checks_ok = String::new();
        let mut checks_fail = String::new();
        let mut sentinels = String::new();
        let mut inputs_kept = String::new();
        let mut elem_sizes = Vec::new();
        let mut variants: Vec<Variant> = Vec::new();
        let v = |param: &str, value: &str, code: String, expect: Expect| Variant {
            param: param.into(),
            value: value.into(),
            code,
            expect,
            length: None,
            index: None,
            stage: Stage::Value,
            mark_null: None,
        };

        for (i, (p, role)) in f.params.iter().zip(roles).enumerate() {
            let first_variant = variants.len();
            let n = &p.name;
            if !c_ident_ok(n) {
                return Err(format!("{fname}: parameter name {n:?}"));
            }
            let ty = p.ty.to_string();
            let _ = writeln!(fields, "    {ty} {n};");
            // The element count an output's checks cover: the nearest length parameter after
            // it, else before it, else a few elements.
            let len_param = f.params[i + 1..]
                .iter()
                .zip(&roles[i + 1..])
                .chain(f.params[..i].iter().zip(&roles[..i]).rev())
                .find(|(_, r)| **r == Role::Length)
                .map(|(q, _)| format!("a->{}", q.name));
            let count = |elem: &str| match &len_param {
                Some(l) => format!("matrix_count({l}, sizeof({elem}))"),
                None => format!("matrix_count(MATRIX_FEW, sizeof({elem}))"),
            };
            let null_expect = || Expect::Only(vec!["OCEAN_STATUS_NULL_POINTER", "OCEAN_STATUS_OK"]);
            let pointer_variants = |variants: &mut Vec<Variant>, align_gt1: bool| {
                variants.push(v(n, "NULL", format!("a.{n} = NULL;"), null_expect()));
                if align_gt1 {
                    variants.push(v(
                        n,
                        "misaligned",
                        format!("a.{n} = ({ty})(void *)(slot[{i}] + 1);"),
                        Expect::Only(vec!["OCEAN_STATUS_MISALIGNED_POINTER"]),
                    ));
                }
            };
            let is_output = matches!(
                role,
                Role::OutHandle { .. }
                    | Role::OutStruct { .. }
                    | Role::OutArray { .. }
                    | Role::OutBytes
                    | Role::OutChars
                    | Role::OutPointer
            );
            let is_input = matches!(role, Role::InStruct { .. } | Role::InArray { .. });
            if is_input {
                let _ = writeln!(sentinels, "    matrix_snapshot({i});");
                let _ = writeln!(inputs_kept, "    matrix_input_kept({i}, \"{n}\");");
            }
            // The element size of an output, for the check that a success wrote no further
            // than its length: `void *` outputs hold at most floats.
            let out_elem = match role {
                Role::OutStruct { name } => Some(name.clone()),
                Role::OutArray { prim } => Some(prim.c().to_owned()),
                Role::OutBytes => Some("float".to_owned()),
                Role::OutChars => Some("char".to_owned()),
                _ => None,
            };
            let extent = documented_extent(f, roles, n).map(|l| format!("a->{l}"));
            if let (Some(elem), Some(l)) = (&out_elem, &extent) {
                let _ = writeln!(
                    checks_ok,
                    "        if ((void *)a->{n} == (void *)slot[{i}])\n            \
                     matrix_written_within({i}, {l}, sizeof({elem}), \"{n}\");"
                );
            }
            if is_output {
                let _ = writeln!(sentinels, "    matrix_sentinel({i});");
                let _ = writeln!(checks_fail, "        matrix_untouched({i}, \"{n}\");");
            }
            if over(n).is_some() {
                let scalar = matches!(
                    role,
                    Role::Float(_)
                        | Role::Length
                        | Role::Index
                        | Role::U32
                        | Role::U8
                        | Role::InString
                );
                if !scalar && !matches!(role, Role::InArray { .. }) {
                    return Err(format!("{fname}: `{n}` ({role:?}) cannot be overridden"));
                }
            }
            match role {
                Role::Handle { kind } => {
                    let k = self.kind_index(kind);
                    if !p.ty.konst {
                        self.mutable.insert(kind.clone());
                    }
                    let _ = writeln!(base, "    a->{n} = ({ty})matrix_live({k});");
                    let invalid = || Expect::Only(vec!["OCEAN_STATUS_INVALID_HANDLE"]);
                    variants.push(v(
                        n,
                        "NULL",
                        format!("a.{n} = NULL;"),
                        Expect::Only(vec!["OCEAN_STATUS_NULL_POINTER"]),
                    ));
                    variants.push(v(
                        n,
                        "another kind",
                        format!("a.{n} = ({ty})matrix_other({k});"),
                        invalid(),
                    ));
                    variants.push(v(
                        n,
                        "destroyed",
                        format!("a.{n} = ({ty})matrix_dead({k});"),
                        invalid(),
                    ));
                    variants.push(v(
                        n,
                        "zeroed memory",
                        format!("a.{n} = ({ty})(void *)foreign_memory;"),
                        invalid(),
                    ));
                    variants.push(v(
                        n,
                        "(void*)1",
                        format!("a.{n} = ({ty})(void *)(uintptr_t)1;"),
                        invalid(),
                    ));
                }
                Role::OutHandle { kind } => {
                    let k = self.kind_index(kind);
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    let _ = writeln!(checks_ok, "        matrix_got_handle({k}, {i}, \"{n}\");");
                    elem_sizes.push("sizeof(void *)".into());
                    pointer_variants(&mut variants, true);
                }
                Role::InStruct { name } => {
                    let fill = self.filler(name);
                    let _ = writeln!(
                        base,
                        "    {fill}(slot[{i}], MATRIX_FILL);\n    a->{n} = ({ty})(void *)slot[{i}];"
                    );
                    elem_sizes.push(format!("sizeof({name})"));
                    pointer_variants(&mut variants, true);
                    let all = struct_leaves(self.h, name)?;
                    // The last element too (one bad member), so that validation must cover
                    // every element, not only the first.
                    let count_after = f.params.get(i + 1).filter(|_| roles[i + 1] == Role::Length);
                    if let (Some(l), Some(leaf)) =
                        (count_after, all.iter().find(|l| l.prim.is_float()))
                    {
                        let l = format!("a.{}", l.name);
                        variants.push(v(
                            &format!("{n}[last]{}", leaf.path),
                            "NaN",
                            format!(
                                "if ({l} > 0 && {l} <= MATRIX_FILL)\n            \
                                 (({name} *)(void *)slot[{i}])[{l} - 1].{} = NAN;",
                                &leaf.path[1..]
                            ),
                            Expect::Any,
                        ));
                    }
                    for leaf in all {
                        for (label, value) in member_values(leaf.prim) {
                            variants.push(v(
                                &format!("{n}[0]{}", leaf.path),
                                label,
                                format!(
                                    "(({name} *)(void *)slot[{i}])->{} = {value};",
                                    &leaf.path[1..]
                                ),
                                Expect::Any,
                            ));
                        }
                    }
                    // Extensions: one of a type no version defines (refused, never ignored),
                    // and a misaligned link (refused before it is read).
                    for link in chain_links(self.h, name) {
                        let at = format!("(({name} *)(void *)slot[{i}])->{}", &link[1..]);
                        variants.push(v(
                            &format!("{n}[0]{link}"),
                            "unknown extension",
                            format!("{at} = &matrix_unknown_extension;"),
                            Expect::IfBaseOk("OCEAN_STATUS_INVALID_ARGUMENT"),
                        ));
                        variants.push(v(
                            &format!("{n}[0]{link}"),
                            "misaligned",
                            format!(
                                "{at} = (const OceanChain *)(const void *)\
                                 (matrix_chain_bytes + 4);"
                            ),
                            Expect::IfBaseOk("OCEAN_STATUS_MISALIGNED_POINTER"),
                        ));
                    }
                }
                Role::OutStruct { name } => {
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    elem_sizes.push(format!("sizeof({name})"));
                    if self.has_float_leaves(name)? {
                        let check = self.checker(name);
                        let _ = writeln!(
                            checks_ok,
                            "        {check}(slot[{i}], {}, \"{n}\");",
                            count(name)
                        );
                    }
                    pointer_variants(&mut variants, true);
                }
                Role::ByValue { name } => {
                    let fill = self.filler(name);
                    let _ = writeln!(base, "    {fill}((unsigned char *)&a->{n}, 1);");
                    for leaf in struct_leaves(self.h, name)? {
                        if !leaf.prim.is_float() {
                            return Err(format!(
                                "{fname}: by-value {name}{} is no float",
                                leaf.path
                            ));
                        }
                        for (label, value) in float_values(leaf.prim) {
                            variants.push(v(
                                &format!("{n}{}", leaf.path),
                                label,
                                format!("a.{n}{} = {value};", leaf.path),
                                Expect::Any,
                            ));
                        }
                    }
                }
                Role::InArray { prim } => {
                    let fill = match (over(n), prim) {
                        (Some(o), _) => o.to_owned(),
                        (None, Prim::F32) => "matrix_fill_f32(buf, MATRIX_FILL, 0.0f, 1.0f)".into(),
                        (None, Prim::F64) => "matrix_fill_f64(buf, MATRIX_FILL)".into(),
                        (None, Prim::U8) => "matrix_fill_u8(buf, MATRIX_FILL)".into(),
                        (None, Prim::U16) => "matrix_fill_u16(buf, MATRIX_FILL)".into(),
                        (None, p) => return Err(format!("{fname}: input array of {p:?}")),
                    };
                    let _ = writeln!(
                        base,
                        "    {{\n        unsigned char *buf = slot[{i}];\n        {fill};\n    }}\n    \
                         a->{n} = ({ty})(void *)slot[{i}];"
                    );
                    elem_sizes.push(format!("sizeof({})", prim.c()));
                    pointer_variants(&mut variants, *prim != Prim::U8);
                    if prim.is_float() {
                        for (label, value) in &float_values(*prim)[..4] {
                            variants.push(v(
                                &format!("{n}[0]"),
                                label,
                                format!("(({} *)(void *)slot[{i}])[0] = {value};", prim.c()),
                                Expect::Any,
                            ));
                        }
                    }
                }
                Role::OutArray { prim } => {
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    elem_sizes.push(format!("sizeof({})", prim.c()));
                    if prim.is_float() {
                        let _ = writeln!(
                            checks_ok,
                            "        matrix_finite_{}(slot[{i}], {}, \"{n}\");",
                            if *prim == Prim::F32 { "f32" } else { "f64" },
                            count(prim.c())
                        );
                    }
                    pointer_variants(&mut variants, *prim != Prim::U8);
                }
                Role::OutBytes => {
                    let _ = writeln!(base, "    a->{n} = (void *)slot[{i}];");
                    // Its element type is chosen by another argument: at most a float.
                    elem_sizes.push("sizeof(float)".into());
                    pointer_variants(&mut variants, false);
                }
                Role::OutChars => {
                    let _ = writeln!(base, "    a->{n} = (char *)slot[{i}];");
                    elem_sizes.push("1".into());
                    pointer_variants(&mut variants, false);
                }
                Role::OutPointer => {
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    elem_sizes.push("sizeof(void *)".into());
                    pointer_variants(&mut variants, true);
                }
                Role::InString => {
                    let s = over(n).unwrap_or("\"\"");
                    let _ = writeln!(base, "    a->{n} = {s};");
                    variants.push(v(n, "NULL", format!("a.{n} = NULL;"), null_expect()));
                    for (label, value) in [
                        ("\\\"\\\"", "\"\""),
                        ("\\\"no such name\\\"", "\"no such name\""),
                        ("\\\"\\\\xff\\\" (not UTF-8)", "\"\\xff\""),
                    ] {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::User => {
                    let _ = writeln!(base, "    a->{n} = &matrix_cookie;");
                    variants.push(v(n, "NULL", format!("a.{n} = NULL;"), Expect::SameAsBase));
                }
                Role::Callback { ty: cb } => {
                    for f in ["count", "cancel"] {
                        if !self.harness.contains(&format!("{f}_{cb}(")) {
                            return Err(format!(
                                "tests/c/matrix_harness.h has no `{f}_{cb}` for {fname}"
                            ));
                        }
                    }
                    let _ = writeln!(base, "    a->{n} = NULL;");
                    variants.push(v(
                        n,
                        "a callback going on",
                        format!("a.{n} = count_{cb};"),
                        Expect::IfBaseOk("OCEAN_STATUS_OK"),
                    ));
                    variants.push(v(
                        n,
                        "a callback cancelling",
                        format!("a.{n} = cancel_{cb};"),
                        Expect::IfBaseOk("OCEAN_STATUS_CANCELLED"),
                    ));
                }
                Role::Float(prim) => {
                    let b = over(n).unwrap_or(if *prim == Prim::F32 { "1.0f" } else { "1.0" });
                    let _ = writeln!(base, "    a->{n} = {b};");
                    for (label, value) in float_values(*prim) {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::Length => {
                    let b = over(n).unwrap_or("4");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    for (label, value) in [
                        ("0", "0"),
                        ("1", "1"),
                        ("SIZE_MAX", "SIZE_MAX"),
                        ("SIZE_MAX/2+1", "SIZE_MAX / 2 + 1"),
                    ] {
                        // Above PTRDIFF_MAX a count overflows whatever its element, and counts
                        // come before values: OCEAN_STATUS_LENGTH_OVERFLOW, never the
                        // LENGTH_MISMATCH of a length that disagrees with a size. A length held
                        // to an exact value answers any other (1 is none of the bases) with
                        // LENGTH_MISMATCH, whatever the buffer: nothing is read or written.
                        let expect = if value.starts_with("SIZE_MAX") {
                            Expect::Only(vec!["OCEAN_STATUS_LENGTH_OVERFLOW"])
                        } else if value == "1" && b != "1" && exact.contains(&n.as_str()) {
                            Expect::IfBaseOk("OCEAN_STATUS_LENGTH_MISMATCH")
                        } else {
                            Expect::Any
                        };
                        let mut var = v(n, label, format!("a.{n} = {value};"), expect);
                        var.length = Some(value.into());
                        variants.push(var);
                    }
                }
                Role::Index => {
                    let b = over(n).unwrap_or("0");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    let mut values = vec![
                        ("1000", "1000"),
                        ("0xFFFFFFFF", "0xFFFFFFFFu"),
                        ("SIZE_MAX", "SIZE_MAX"),
                    ];
                    if b != "0" {
                        values.push(("0", "0"));
                    }
                    for (label, value) in values {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::U32 => {
                    let b = over(n).unwrap_or("0");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    let mut values = vec![("0xFFFFFFFF", "0xFFFFFFFFu"), ("1000", "1000")];
                    if b != "0" {
                        values.push(("0", "0"));
                    }
                    for (label, value) in values {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::U8 => {
                    let b = over(n).unwrap_or("0");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    for (label, value) in [("2", "2"), ("255", "255")] {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
            }
            let pointer = !matches!(
                role,
                Role::Handle { .. }
                    | Role::User
                    | Role::Callback { .. }
                    | Role::Float(_)
                    | Role::Length
                    | Role::Index
                    | Role::U32
                    | Role::U8
                    | Role::ByValue { .. }
            );
            for var in &mut variants[first_variant..] {
                var.index = Some(i);
                var.stage = if matches!(role, Role::Handle { .. }) {
                    Stage::Handle
                } else if pointer
                    && var.param == *n
                    && matches!(var.value.as_str(), "NULL" | "misaligned")
                {
                    Stage::Pointer
                } else {
                    Stage::Value
                };
                if var.stage == Stage::Pointer && var.value == "NULL" {
                    var.mark_null = Some(i);
                }
            }
        }

        // The error order (header preamble): a bad handle is reported before anything else,
        // and a NULL pointer that is refused alone before any bad count or value. Each single
        // variant is run again with the first handle destroyed, and with each required pointer
        // NULL.
        let mut ordered = Vec::new();
        if let Some(h) = roles.iter().position(|r| matches!(r, Role::Handle { .. })) {
            let Role::Handle { kind } = &roles[h] else {
                unreachable!()
            };
            let (hn, hty, k) = (
                &f.params[h].name,
                f.params[h].ty.to_string(),
                self.kind_index(kind),
            );
            for var in variants.iter().filter(|x| x.index.is_some_and(|i| i != h)) {
                ordered.push(Variant {
                    param: format!("{hn}=destroyed, {}", var.param),
                    code: format!("{}\n        a.{hn} = ({hty})matrix_dead({k});", var.code),
                    expect: Expect::Only(vec!["OCEAN_STATUS_INVALID_HANDLE"]),
                    index: None,
                    mark_null: None,
                    ..var.clone()
                });
            }
        }
        for (i, p) in f.params.iter().enumerate() {
            let refused_alone = variants
                .iter()
                .any(|x| x.index == Some(i) && x.stage == Stage::Pointer && x.value == "NULL");
            if !refused_alone {
                continue;
            }
            let later = variants.iter().filter(|x| {
                x.stage == Stage::Value
                    && x.index.is_some_and(|j| j != i)
                    // NULL with a length of 0 is the documented "nothing" or size query.
                    && x.length.as_deref() != Some("0")
            });
            for var in later {
                ordered.push(Variant {
                    param: format!("{}=NULL, {}", p.name, var.param),
                    code: format!("{}\n        a.{} = NULL;", var.code, p.name),
                    expect: Expect::IfNullRefused(i),
                    index: None,
                    mark_null: None,
                    ..var.clone()
                });
            }
        }

        let args: Vec<String> = f.params.iter().map(|p| format!("a->{}", p.name)).collect();
        let id = fname;
        let fields = if fields.is_empty() {
            "    int unused;\n".to_owned()
        } else {
            fields
        };
        let max_elem = if elem_sizes.is_empty() {
            "1".to_owned()
        } else {
            elem_sizes.iter().fold(String::from("1"), |acc, s| {
                format!("MATRIX_MAX({acc}, {s})")
            })
        };
        let mut c = String::new();
        let _ = write!(
            c,
            "/* {ret} {fname}({sig}) */\n\
             typedef struct {{\n{fields}}} A_{id};\n\n\
             static void base_{id}(A_{id} *a)\n{{\n    (void)a;\n{base}}}\n\n\
             static void call_{id}(A_{id} *a)\n{{\n    OceanStatus s;\n{sentinels}    \
             matrix_pre_call();\n    s = {fname}({args});\n    matrix_post_call(s);\n{inputs_kept}    \
             if (s == OCEAN_STATUS_OK) {{\n{checks_ok}        (void)0;\n    }} else {{\n\
             {checks_fail}        (void)0;\n    }}\n}}\n\n\
             static void run_{id}(void)\n{{\n    A_{id} a;\n    \
             const size_t max_elem = {max_elem};\n    (void)max_elem;\n    \
             matrix_function(\"{fname}\");\n",
            ret = f.ret,
            sig = f
                .params
                .iter()
                .map(|p| format!("{} {}", p.ty, p.name))
                .collect::<Vec<_>>()
                .join(", "),
            args = args.join(", "),
        );
        for (p, role) in f.params.iter().zip(roles) {
            if let Role::Handle { kind } = role
                && !p.ty.konst
            {
                let _ = writeln!(c, "    matrix_refresh({});", self.kind_index(kind));
            }
        }
        let _ = write!(
            c,
            "    if (matrix_begin(\"(base)\", \"plausible arguments\")) {{\n        \
             base_{id}(&a);\n        call_{id}(&a);\n    }}\n"
        );
        variants.extend(ordered);
        for var in &variants {
            let expect = match &var.expect {
                Expect::Any => String::new(),
                Expect::Only(list) => format!(
                    "        matrix_expect({});\n",
                    list.iter()
                        .map(|s| format!("MATRIX_BIT({s})"))
                        .collect::<Vec<_>>()
                        .join(" | ")
                ),
                Expect::IfBaseOk(s) => format!("        matrix_expect_if_base_ok({s});\n"),
                Expect::SameAsBase => "        matrix_expect_same_as_base();\n".into(),
                Expect::IfNullRefused(i) => {
                    format!("        matrix_expect_if_null_refused({i});\n")
                }
            };
            let expect = match var.mark_null {
                Some(i) => format!("        matrix_mark_null({i});\n{expect}"),
                None => expect,
            };
            let guard = var
                .length
                .as_ref()
                .map(|l| format!("matrix_length_ok({l}, max_elem) && "))
                .unwrap_or_default();
            let _ = write!(
                c,
                "    if ({guard}matrix_begin(\"{p}\", \"{val}\")) {{\n        base_{id}(&a);\n        \
                 {code}\n{expect}        call_{id}(&a);\n    }}\n",
                p = var.param,
                val = var.value,
                code = var.code,
            );
        }
        if roles.iter().any(|r| matches!(r, Role::Handle { .. })) {
            let _ = writeln!(c, "    matrix_foreign_untouched();");
        }
        c.push_str("}\n\n");
        self.variants += variants.len() + 1;
        self.out.push_str(&c);
        Ok(())
    }
}
