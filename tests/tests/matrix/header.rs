//! A parser for the C text of `include/ocean.h`: the structs, opaque handle types, enums,
//! function-pointer types and function prototypes that cbindgen writes.
//!
//! cbindgen's output is regular (one declaration per statement, `struct` spelled out in
//! parameter types, no macros in declarations), so a small lexer and a recursive-descent parser
//! read all of it. What they do not recognise is an error, never a silent skip: a construct
//! cbindgen starts emitting later must be taught here before the matrix runs again.

use std::fmt;

/// The base of a C type: a named type (`double`, `uint32_t`, `OceanStatus`, a function-pointer
/// typedef) or `struct Name`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Base {
    Named(String),
    Struct(String),
}

/// A C type as cbindgen writes it: `[const] base *...*` (`const` only ever qualifies the base).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CType {
    pub konst: bool,
    pub base: Base,
    pub stars: usize,
}

impl CType {
    /// The name of the base type, without `struct`.
    pub fn base_name(&self) -> &str {
        match &self.base {
            Base::Named(n) | Base::Struct(n) => n,
        }
    }

    /// The same type with one pointer level removed.
    pub fn pointee(&self) -> CType {
        assert!(self.stars > 0, "{self} is not a pointer");
        CType {
            stars: self.stars - 1,
            ..self.clone()
        }
    }
}

impl fmt::Display for CType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.konst {
            f.write_str("const ")?;
        }
        match &self.base {
            Base::Named(n) => f.write_str(n)?,
            Base::Struct(n) => write!(f, "struct {n}")?,
        }
        if self.stars > 0 {
            write!(f, " {}", "*".repeat(self.stars))?;
        }
        Ok(())
    }
}

/// A struct member: `type name[d0][d1]...;` and its documentation.
#[derive(Clone, Debug)]
pub struct Member {
    pub name: String,
    pub ty: CType,
    pub dims: Vec<usize>,
    pub doc: String,
}

#[derive(Clone, Debug)]
pub struct Struct {
    pub name: String,
    pub members: Vec<Member>,
}

#[derive(Clone, Debug)]
pub struct Enum {
    pub name: String,
    pub values: Vec<(String, u64)>,
}

#[derive(Clone, Debug)]
pub struct Param {
    pub name: String,
    pub ty: CType,
}

#[derive(Clone, Debug)]
pub struct Function {
    pub name: String,
    pub ret: CType,
    pub params: Vec<Param>,
    /// The documentation comment before the prototype.
    pub doc: String,
}

/// Everything the matrix needs from the header.
#[derive(Debug, Default)]
pub struct Header {
    /// `typedef struct X X;`: the opaque handle types.
    pub opaque: Vec<String>,
    pub structs: Vec<Struct>,
    pub enums: Vec<Enum>,
    /// `typedef uint32_t X;` (the C11 spelling of the enums).
    pub aliases: Vec<(String, String)>,
    /// `typedef R (*X)(...);`.
    pub fn_types: Vec<String>,
    /// `typedef const struct X *Y;`: pointer types, replaced by what they name wherever a
    /// member or parameter uses them.
    pub pointers: Vec<(String, CType)>,
    pub functions: Vec<Function>,
    /// `#define NAME value`.
    pub defines: Vec<(String, String)>,
}

impl Header {
    /// `ty` with a pointer typedef replaced by the type it names.
    fn resolve(&self, ty: CType) -> CType {
        match self
            .pointers
            .iter()
            .find(|(n, _)| ty.stars == 0 && n == ty.base_name())
        {
            Some((_, named)) => named.clone(),
            None => ty,
        }
    }

    pub fn parse(text: &str) -> Result<Header, String> {
        let mut header = Header::default();
        let tokens = lex(text, &mut header.defines)?;
        Parser {
            toks: &tokens,
            pos: 0,
        }
        .parse(&mut header)?;
        Ok(header)
    }

    pub fn struct_def(&self, name: &str) -> Option<&Struct> {
        self.structs.iter().find(|s| s.name == name)
    }

    pub fn is_opaque(&self, name: &str) -> bool {
        self.opaque.iter().any(|o| o == name)
    }

    pub fn enum_def(&self, name: &str) -> Option<&Enum> {
        self.enums.iter().find(|e| e.name == name)
    }
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Num(String),
    Punct(char),
    /// A `/** ... */` comment, its text without the stars.
    Doc(String),
}

/// The value of the `#if` conditions the header uses, for a C11 compiler (no `__cplusplus`,
/// `__STDC_VERSION__` 201112L) building against the full library (`OCEAN_GPU` defined, as the
/// matrix program is compiled: `c_build::FULL_LIBRARY`). Unknown conditions are errors.
fn condition(directive: &str, rest: &str) -> Result<bool, String> {
    let rest = rest.split("//").next().unwrap_or("").trim();
    match (directive, rest) {
        ("ifndef", "OCEAN_H") => Ok(true),
        ("ifdef", "__cplusplus") => Ok(false),
        ("ifndef", "__cplusplus") => Ok(true),
        ("if", "defined(OCEAN_GPU)") => Ok(true),
        ("if", "__STDC_VERSION__ >= 202311L") => Ok(false),
        ("if", "defined(__cplusplus) || __STDC_VERSION__ >= 202311L") => Ok(false),
        _ => Err(format!(
            "unknown preprocessor condition `#{directive} {rest}`"
        )),
    }
}

/// Splits the header into tokens, evaluating the preprocessor for C11 and dropping what it
/// excludes; `#define`s are collected.
fn lex(text: &str, defines: &mut Vec<(String, String)>) -> Result<Vec<Tok>, String> {
    let chars: Vec<char> = text.chars().collect();
    let mut toks = Vec::new();
    // One entry per open #if: (this branch active, some branch taken).
    let mut stack: Vec<(bool, bool)> = Vec::new();
    let active = |stack: &[(bool, bool)]| stack.iter().all(|(a, _)| *a);
    let mut i = 0;
    let mut line_start = true;
    while i < chars.len() {
        let c = chars[i];
        if c == '\n' {
            line_start = true;
            i += 1;
            continue;
        }
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c == '#' && line_start {
            let end = chars[i..]
                .iter()
                .position(|&c| c == '\n')
                .map_or(chars.len(), |p| i + p);
            let line: String = chars[i + 1..end].iter().collect();
            let line = line.trim();
            let (directive, rest) = line.split_once(char::is_whitespace).unwrap_or((line, ""));
            match directive {
                "if" | "ifdef" | "ifndef" => {
                    let value = condition(directive, rest)?;
                    stack.push((value, value));
                }
                "else" => {
                    let top = stack.last_mut().ok_or("#else without #if")?;
                    *top = (!top.1, true);
                }
                "endif" => {
                    stack.pop().ok_or("#endif without #if")?;
                }
                "include" => {}
                "define" if active(&stack) => {
                    let (name, value) = rest.trim().split_once(' ').unwrap_or((rest.trim(), ""));
                    defines.push((name.to_owned(), value.trim().to_owned()));
                }
                "define" => {}
                _ => return Err(format!("unknown preprocessor directive `#{line}`")),
            }
            i = end;
            continue;
        }
        line_start = false;
        if chars[i..].starts_with(&['/', '*']) {
            let end = (i + 2..chars.len().saturating_sub(1))
                .find(|&j| chars[j] == '*' && chars[j + 1] == '/')
                .ok_or("unterminated comment")?;
            let doc = chars.get(i + 2) == Some(&'*') && end > i + 2;
            if doc && active(&stack) {
                let body: String = chars[i + 3..end].iter().collect();
                let text = body
                    .lines()
                    .map(|l| l.trim().trim_start_matches('*').trim())
                    .collect::<Vec<_>>()
                    .join("\n");
                toks.push(Tok::Doc(text.trim().to_owned()));
            }
            i = end + 2;
            continue;
        }
        if chars[i..].starts_with(&['/', '/']) {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
            continue;
        }
        if !active(&stack) {
            i += 1;
            continue;
        }
        let start = i;
        let tok = if c.is_ascii_alphabetic() || c == '_' {
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            Tok::Ident(chars[start..i].iter().collect())
        } else if c.is_ascii_digit() {
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '.') {
                i += 1;
            }
            Tok::Num(chars[start..i].iter().collect())
        } else if "{}()[];,*=".contains(c) {
            i += 1;
            Tok::Punct(c)
        } else {
            return Err(format!(
                "unexpected character {c:?} at offset {i} of the header"
            ));
        };
        toks.push(tok);
    }
    if !stack.is_empty() {
        return Err("unterminated #if".into());
    }
    Ok(toks)
}

struct Parser<'a> {
    toks: &'a [Tok],
    pos: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos)
    }

    fn next(&mut self) -> Result<Tok, String> {
        let t = self.toks.get(self.pos).cloned().ok_or("unexpected end")?;
        self.pos += 1;
        Ok(t)
    }

    fn ident(&mut self) -> Result<String, String> {
        match self.next()? {
            Tok::Ident(s) => Ok(s),
            t => Err(format!("expected an identifier, found {t:?}{}", self.at())),
        }
    }

    fn punct(&mut self, c: char) -> Result<(), String> {
        match self.next()? {
            Tok::Punct(p) if p == c => Ok(()),
            t => Err(format!("expected `{c}`, found {t:?}{}", self.at())),
        }
    }

    fn at(&self) -> String {
        let near: Vec<String> = self.toks[self.pos.saturating_sub(6)..self.pos]
            .iter()
            .filter_map(|t| match t {
                Tok::Ident(s) | Tok::Num(s) => Some(s.clone()),
                Tok::Punct(c) => Some(c.to_string()),
                Tok::Doc(_) => None,
            })
            .collect();
        format!(" (after `{}`)", near.join(" "))
    }

    /// The tokens up to (not including) the next `stop` at bracket depth 0, docs dropped.
    fn until(&mut self, stop: char) -> Result<Vec<Tok>, String> {
        let mut depth = 0i32;
        let mut out = Vec::new();
        loop {
            let t = self.peek().cloned().ok_or("unexpected end")?;
            match t {
                Tok::Punct(c) if c == stop && depth == 0 => return Ok(out),
                Tok::Punct('(' | '[' | '{') => depth += 1,
                Tok::Punct(')' | ']' | '}') => depth -= 1,
                _ => {}
            }
            self.pos += 1;
            if !matches!(t, Tok::Doc(_)) {
                out.push(t);
            }
            if depth < 0 {
                return Err(format!("unbalanced brackets{}", self.at()));
            }
        }
    }

    fn parse(&mut self, h: &mut Header) -> Result<(), String> {
        let mut doc = String::new();
        while let Some(t) = self.peek().cloned() {
            match t {
                Tok::Doc(d) => {
                    doc = d;
                    self.pos += 1;
                    continue;
                }
                Tok::Ident(ref s) if s == "typedef" => self.typedef(h)?,
                Tok::Ident(ref s) if s == "enum" => self.enumeration(h)?,
                _ => {
                    let f = self.function(std::mem::take(&mut doc))?;
                    h.functions.push(f);
                }
            }
            doc.clear();
        }
        Ok(())
    }

    fn typedef(&mut self, h: &mut Header) -> Result<(), String> {
        self.ident()?; // typedef
        let first = self.ident()?;
        match first.as_str() {
            "struct" => {
                let name = self.ident()?;
                match self.next()? {
                    Tok::Ident(alias) if alias == name => {
                        self.punct(';')?;
                        h.opaque.push(name);
                    }
                    Tok::Punct('{') => {
                        let mut members = Vec::new();
                        let mut doc = String::new();
                        loop {
                            match self.peek().cloned().ok_or("unexpected end")? {
                                Tok::Doc(d) => {
                                    doc = d;
                                    self.pos += 1;
                                }
                                Tok::Punct('}') => {
                                    self.pos += 1;
                                    break;
                                }
                                _ => {
                                    let decl = self.until(';')?;
                                    self.punct(';')?;
                                    let (ty, name, dims) = declaration(&decl)
                                        .map_err(|e| format!("struct {name}: {e}"))?;
                                    let ty = h.resolve(ty);
                                    members.push(Member {
                                        name,
                                        ty,
                                        dims,
                                        doc: std::mem::take(&mut doc),
                                    });
                                }
                            }
                        }
                        let alias = self.ident()?;
                        if alias != name {
                            return Err(format!("struct {name} typedef'd as {alias}"));
                        }
                        self.punct(';')?;
                        h.structs.push(Struct { name, members });
                    }
                    t => return Err(format!("typedef struct {name}: unexpected {t:?}")),
                }
            }
            "enum" => {
                // The C23 spelling; excluded by the preprocessor for C11, kept for safety.
                let _ = self.until(';')?;
                self.punct(';')?;
            }
            "const" => {
                // typedef const struct X *Y;
                let mut decl = vec![Tok::Ident(first)];
                decl.extend(self.until(';')?);
                self.punct(';')?;
                let (ty, name, dims) = declaration(&decl)?;
                if ty.stars == 0 || !dims.is_empty() {
                    return Err(format!("typedef {name}: not a pointer type"));
                }
                h.pointers.push((name, ty));
            }
            _ => {
                if let Some(Tok::Punct('(')) = self.peek() {
                    // typedef R (*Name)(params);
                    self.punct('(')?;
                    self.punct('*')?;
                    let name = self.ident()?;
                    self.punct(')')?;
                    self.punct('(')?;
                    let _ = self.until(')')?;
                    self.punct(')')?;
                    self.punct(';')?;
                    h.fn_types.push(name);
                } else {
                    let alias = self.ident()?;
                    self.punct(';')?;
                    h.aliases.push((alias, first));
                }
            }
        }
        Ok(())
    }

    fn enumeration(&mut self, h: &mut Header) -> Result<(), String> {
        self.ident()?; // enum
        let name = self.ident()?;
        self.punct('{')?;
        let body = self.until('}')?;
        self.punct('}')?;
        self.punct(';')?;
        let mut values = Vec::new();
        for item in body.split(|t| *t == Tok::Punct(',')) {
            match item {
                [] => {}
                [Tok::Ident(n), Tok::Punct('='), Tok::Num(v)] => {
                    let v = v
                        .parse()
                        .map_err(|e| format!("enum {name}: value {v}: {e}"))?;
                    values.push((n.clone(), v));
                }
                other => return Err(format!("enum {name}: cannot read {other:?}")),
            }
        }
        h.enums.push(Enum { name, values });
        Ok(())
    }

    fn function(&mut self, doc: String) -> Result<Function, String> {
        let head = self.until('(')?;
        self.punct('(')?;
        let params = self.until(')')?;
        self.punct(')')?;
        self.punct(';')?;
        let (ret, name, dims) = declaration(&head)?;
        if !dims.is_empty() {
            return Err(format!("{name}: array return type"));
        }
        let mut out = Vec::new();
        if params != [Tok::Ident("void".into())] {
            for p in params.split(|t| *t == Tok::Punct(',')) {
                let (ty, pname, dims) = declaration(p).map_err(|e| format!("{name}: {e}"))?;
                if !dims.is_empty() {
                    return Err(format!("{name}: array parameter {pname}"));
                }
                out.push(Param { name: pname, ty });
            }
        }
        Ok(Function {
            name,
            ret,
            params: out,
            doc,
        })
    }
}

/// Reads `[const] [struct] T *... name [N]...`.
fn declaration(toks: &[Tok]) -> Result<(CType, String, Vec<usize>), String> {
    let mut i = 0;
    let word = |i: usize| match toks.get(i) {
        Some(Tok::Ident(s)) => Some(s.as_str()),
        _ => None,
    };
    let konst = word(0) == Some("const");
    if konst {
        i += 1;
    }
    let base = if word(i) == Some("struct") {
        i += 2;
        Base::Struct(word(i - 1).ok_or("`struct` without a name")?.to_owned())
    } else {
        i += 1;
        Base::Named(
            word(i - 1)
                .ok_or(format!("no type in {toks:?}"))?
                .to_owned(),
        )
    };
    let mut stars = 0;
    while toks.get(i) == Some(&Tok::Punct('*')) {
        stars += 1;
        i += 1;
    }
    let name = word(i).ok_or(format!("no name in {toks:?}"))?.to_owned();
    i += 1;
    let mut dims = Vec::new();
    while i < toks.len() {
        match &toks[i..] {
            [Tok::Punct('['), Tok::Num(n), Tok::Punct(']'), ..] => {
                dims.push(n.parse().map_err(|e| format!("dimension {n}: {e}"))?);
                i += 3;
            }
            rest => return Err(format!("cannot read {rest:?} after `{name}`")),
        }
    }
    Ok((CType { konst, base, stars }, name, dims))
}
