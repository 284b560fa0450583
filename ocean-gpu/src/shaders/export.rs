//! Translation of a registered shader to another shading language through naga, with its
//! resource bindings ([`export`]).

use super::*;

/// Target language of [`export`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Language {
    /// Desktop GLSL: 4.30 core for compute passes, 3.30 core for draw passes.
    Glsl,
    /// GLSL ES 3.10.
    GlslEs,
    /// HLSL, Shader Model 5.1.
    Hlsl,
    /// Metal Shading Language 2.0.
    Msl,
    /// SPIR-V 1.0 binary.
    SpirV,
}

impl Language {
    /// Every language, in CLI order.
    pub const ALL: [Language; 5] = [
        Language::Glsl,
        Language::GlslEs,
        Language::Hlsl,
        Language::Msl,
        Language::SpirV,
    ];

    /// The CLI spelling: `glsl`, `glsles`, `hlsl`, `msl`, `spirv`.
    pub fn name(self) -> &'static str {
        match self {
            Language::Glsl => "glsl",
            Language::GlslEs => "glsles",
            Language::Hlsl => "hlsl",
            Language::Msl => "msl",
            Language::SpirV => "spirv",
        }
    }
}

impl fmt::Display for Language {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Language {
    type Err = ShaderError;

    /// Parses the CLI spelling (case-insensitive); `spv`, `metal` and `essl` are accepted too.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Ok(match s.to_ascii_lowercase().as_str() {
            "glsl" => Language::Glsl,
            "glsles" | "essl" => Language::GlslEs,
            "hlsl" => Language::Hlsl,
            "msl" | "metal" => Language::Msl,
            "spirv" | "spv" => Language::SpirV,
            _ => return Err(ShaderError::UnknownLanguage(s.to_owned())),
        })
    }
}

/// What kind of resource a binding is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BindingKind {
    /// A uniform buffer.
    Uniform,
    /// A read-only storage buffer.
    StorageRead,
    /// A read-write storage buffer.
    StorageReadWrite,
    /// A sampled (or depth) texture.
    Texture,
    /// A storage texture; `read`/`write` access as declared.
    StorageTexture {
        /// Readable.
        read: bool,
        /// Writable.
        write: bool,
    },
    /// A sampler (`comparison` for depth comparisons).
    Sampler {
        /// Comparison sampler.
        comparison: bool,
    },
}

impl fmt::Display for BindingKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            BindingKind::Uniform => f.write_str("uniform"),
            BindingKind::StorageRead => f.write_str("storage(read)"),
            BindingKind::StorageReadWrite => f.write_str("storage(read_write)"),
            BindingKind::Texture => f.write_str("texture"),
            BindingKind::StorageTexture { read, write } => {
                let access = match (read, write) {
                    (true, true) => "read_write",
                    (true, false) => "read",
                    _ => "write",
                };
                write!(f, "storage_texture({access})")
            }
            BindingKind::Sampler { comparison: false } => f.write_str("sampler"),
            BindingKind::Sampler { comparison: true } => f.write_str("sampler_comparison"),
        }
    }
}

/// A member of a struct bound as a buffer, with its byte offset (std140/std430 as WGSL lays it
/// out, which every export keeps).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Member {
    /// Member name.
    pub name: String,
    /// Byte offset in the struct.
    pub offset: u32,
    /// WGSL type.
    pub ty: String,
}

/// One resource binding of a shader.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Binding {
    /// WGSL `@group`.
    pub group: u32,
    /// WGSL `@binding`.
    pub binding: u32,
    /// Variable name in the WGSL source.
    pub name: String,
    /// Resource kind.
    pub kind: BindingKind,
    /// WGSL type of the variable, e.g. `array<vec4<f32>>`.
    pub ty: String,
    /// Byte size of the type, or of one element for a runtime-sized array.
    pub size: u32,
    /// The struct's members (or the array element struct's), with offsets; empty otherwise.
    pub members: Vec<Member>,
    /// In a GLSL export: the name of the block or sampler naga wrote for this binding.
    pub glsl_name: Option<String>,
    /// In a GLSL export: the flattened binding number (see the module docs), written as
    /// `layout(binding = n)` in GLSL 4.30 and ES 3.10; `None` for GLSL 3.30 (assign it by
    /// name) and samplers (combined with their texture in GLSL).
    pub glsl_binding: Option<u32>,
}

/// Output code: text, or SPIR-V bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Code {
    /// Source text.
    Text(String),
    /// SPIR-V module, little-endian 32-bit words.
    Binary(Vec<u8>),
}

impl Code {
    /// The bytes to write to a file.
    pub fn as_bytes(&self) -> &[u8] {
        match self {
            Code::Text(s) => s.as_bytes(),
            Code::Binary(b) => b,
        }
    }
}

/// One output file of an export.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExportFile {
    /// Suggested file name, e.g. `trochoid.displace.comp.glsl`, `trochoid.hlsl`,
    /// `trochoid.metal`, `trochoid.spv`.
    pub file_name: String,
    /// The entry point this file holds, for languages with one entry point per file (GLSL).
    pub entry_point: Option<String>,
    /// Its stage, for per-entry-point files.
    pub stage: Option<Stage>,
    /// The code.
    pub code: Code,
}

/// A shader translated to one language, with its binding layout.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Export {
    /// Registry name of the shader.
    pub shader: &'static str,
    /// Target language.
    pub language: Language,
    /// Output files.
    pub files: Vec<ExportFile>,
    /// Resource bindings, in (group, binding) order.
    pub bindings: Vec<Binding>,
}

impl Export {
    /// The binding layout as a plain-text table, one binding per line, for a `bindings.txt`
    /// next to the exported files.
    pub fn bindings_table(&self) -> String {
        let mut out = format!("# {} ({}): resource bindings\n", self.shader, self.language);
        out.push_str("# group binding name kind type [glsl name, glsl binding]\n");
        for b in &self.bindings {
            out.push_str(&format!(
                "{} {} {} {} {} (size {})",
                b.group, b.binding, b.name, b.kind, b.ty, b.size
            ));
            if let Some(n) = &b.glsl_name {
                out.push_str(&format!(" glsl_name={n}"));
            }
            if let Some(n) = b.glsl_binding {
                out.push_str(&format!(" glsl_binding={n}"));
            }
            out.push('\n');
            for m in &b.members {
                out.push_str(&format!("    +{} {}: {}\n", m.offset, m.name, m.ty));
            }
        }
        out
    }
}

pub(super) fn members_of(module: &naga::Module, ty: naga::Handle<naga::Type>) -> Vec<Member> {
    let inner = match module.types[ty].inner {
        naga::TypeInner::Array { base, .. } => &module.types[base].inner,
        ref other => other,
    };
    match inner {
        naga::TypeInner::Struct { members, .. } => members
            .iter()
            .map(|m| Member {
                name: m.name.clone().unwrap_or_default(),
                offset: m.offset,
                ty: module.types.type_to_string(m.ty),
            })
            .collect(),
        _ => Vec::new(),
    }
}

pub(super) fn bindings_of(module: &naga::Module) -> Vec<Binding> {
    let mut out: Vec<Binding> = module
        .global_variables
        .iter()
        .filter_map(|(_, var)| {
            let rb = var.binding.as_ref()?;
            let inner = &module.types[var.ty].inner;
            let kind = match (var.space, inner) {
                (naga::AddressSpace::Uniform, _) => BindingKind::Uniform,
                (naga::AddressSpace::Storage { access }, _) => {
                    if access.contains(naga::StorageAccess::STORE) {
                        BindingKind::StorageReadWrite
                    } else {
                        BindingKind::StorageRead
                    }
                }
                (_, naga::TypeInner::Sampler { comparison }) => BindingKind::Sampler {
                    comparison: *comparison,
                },
                (
                    _,
                    naga::TypeInner::Image {
                        class: naga::ImageClass::Storage { access, .. },
                        ..
                    },
                ) => BindingKind::StorageTexture {
                    read: access.contains(naga::StorageAccess::LOAD),
                    write: access.contains(naga::StorageAccess::STORE),
                },
                _ => BindingKind::Texture,
            };
            let size = match *inner {
                naga::TypeInner::Array {
                    size: naga::ArraySize::Dynamic,
                    stride,
                    ..
                } => stride,
                _ => inner.size(module.to_ctx()),
            };
            Some(Binding {
                group: rb.group,
                binding: rb.binding,
                name: var.name.clone().unwrap_or_default(),
                kind,
                ty: module.types.type_to_string(var.ty),
                size,
                members: members_of(module, var.ty),
                glsl_name: None,
                glsl_binding: None,
            })
        })
        .collect();
    out.sort_by_key(|b| (b.group, b.binding));
    out
}

/// GL binding namespaces: each is numbered from 0 independently.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum GlNamespace {
    UniformBlock,
    StorageBlock,
    TextureUnit,
    ImageUnit,
}

pub(super) fn gl_namespace(kind: BindingKind) -> Option<GlNamespace> {
    match kind {
        BindingKind::Uniform => Some(GlNamespace::UniformBlock),
        BindingKind::StorageRead | BindingKind::StorageReadWrite => Some(GlNamespace::StorageBlock),
        BindingKind::Texture => Some(GlNamespace::TextureUnit),
        BindingKind::StorageTexture { .. } => Some(GlNamespace::ImageUnit),
        BindingKind::Sampler { .. } => None,
    }
}

/// The flattened GL binding of every non-sampler binding (see the module docs).
pub(super) fn gl_binding_numbers(bindings: &[Binding]) -> BTreeMap<(u32, u32), u32> {
    let mut next: BTreeMap<GlNamespace, u32> = BTreeMap::new();
    let mut out = BTreeMap::new();
    for b in bindings {
        if let Some(ns) = gl_namespace(b.kind) {
            let n = next.entry(ns).or_insert(0);
            out.insert((b.group, b.binding), *n);
            *n += 1;
        }
    }
    out
}

/// Translates the shader `name` to `language` and lists its bindings.
pub fn export(name: &str, language: Language) -> Result<Export, ShaderError> {
    let entry = get(name).ok_or_else(|| ShaderError::UnknownShader {
        name: name.to_owned(),
        available: all().iter().map(|s| s.name).collect::<Vec<_>>().join(", "),
    })?;
    entry.export(language)
}

impl ShaderEntry {
    /// Translates this shader to `language` and lists its bindings.
    pub fn export(&self, language: Language) -> Result<Export, ShaderError> {
        let (module, info) = self.module()?;
        let mut bindings = bindings_of(&module);
        let translation = |message: String| ShaderError::Translation {
            name: self.name,
            language,
            message,
        };
        let files = match language {
            Language::Glsl | Language::GlslEs => {
                self.export_glsl(&module, &info, language, &mut bindings)?
            }
            Language::Hlsl => {
                let options = naga::back::hlsl::Options::default();
                let pipeline = naga::back::hlsl::PipelineOptions::default();
                let mut text = String::new();
                naga::back::hlsl::Writer::new(&mut text, &options, &pipeline)
                    .write(&module, &info, None)
                    .map_err(|e| translation(e.to_string()))?;
                vec![ExportFile {
                    file_name: format!("{}.hlsl", self.name),
                    entry_point: None,
                    stage: None,
                    code: Code::Text(text),
                }]
            }
            Language::Msl => {
                let options = naga::back::msl::Options {
                    lang_version: (2, 0),
                    ..Default::default()
                };
                let pipeline = naga::back::msl::PipelineOptions::default();
                let (text, _) = naga::back::msl::write_string(&module, &info, &options, &pipeline)
                    .map_err(|e| translation(e.to_string()))?;
                vec![ExportFile {
                    file_name: format!("{}.metal", self.name),
                    entry_point: None,
                    stage: None,
                    code: Code::Text(text),
                }]
            }
            Language::SpirV => {
                // No DEBUG flag: debug builds would otherwise embed names and source, and the
                // output would differ between debug and release builds.
                let options = naga::back::spv::Options {
                    flags: naga::back::spv::WriterFlags::ADJUST_COORDINATE_SPACE
                        | naga::back::spv::WriterFlags::LABEL_VARYINGS
                        | naga::back::spv::WriterFlags::CLAMP_FRAG_DEPTH,
                    ..Default::default()
                };
                let words = naga::back::spv::write_vec(&module, &info, &options, None)
                    .map_err(|e| translation(e.to_string()))?;
                vec![ExportFile {
                    file_name: format!("{}.spv", self.name),
                    entry_point: None,
                    stage: None,
                    code: Code::Binary(words.iter().flat_map(|w| w.to_le_bytes()).collect()),
                }]
            }
        };
        Ok(Export {
            shader: self.name,
            language,
            files,
            bindings,
        })
    }

    fn export_glsl(
        &self,
        module: &naga::Module,
        info: &ModuleInfo,
        language: Language,
        bindings: &mut [Binding],
    ) -> Result<Vec<ExportFile>, ShaderError> {
        let version = match (language, self.kind) {
            (Language::GlslEs, _) => naga::back::glsl::Version::new_gles(310),
            (_, ShaderKind::Compute) => naga::back::glsl::Version::Desktop(430),
            (_, ShaderKind::Draw) => naga::back::glsl::Version::Desktop(330),
        };
        let explicit = version.supports_explicit_locations();
        let numbers = gl_binding_numbers(bindings);
        let mut binding_map = naga::back::glsl::BindingMap::default();
        for (&(group, binding), &n) in &numbers {
            let n = u8::try_from(n).map_err(|_| ShaderError::Translation {
                name: self.name,
                language,
                message: format!("GL binding number {n} exceeds 255"),
            })?;
            binding_map.insert(naga::ResourceBinding { group, binding }, n);
        }
        let options = naga::back::glsl::Options {
            version,
            // ADJUST_COORDINATE_SPACE flips y and remaps depth for GL's clip space in vertex
            // shaders, as wgpu's GL backend does.
            writer_flags: naga::back::glsl::WriterFlags::ADJUST_COORDINATE_SPACE,
            binding_map,
            zero_initialize_workgroup_memory: true,
        };
        let mut files = Vec::new();
        for ep in self.entry_points {
            let pipeline = naga::back::glsl::PipelineOptions {
                shader_stage: ep.stage.to_naga(),
                entry_point: ep.name.to_owned(),
                multiview: None,
            };
            let mut text = String::new();
            let reflection = naga::back::glsl::Writer::new(
                &mut text,
                module,
                info,
                &options,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .and_then(|mut w| w.write())
            .map_err(|e| ShaderError::Translation {
                name: self.name,
                language,
                message: format!("entry point {}: {e}", ep.name),
            })?;
            // Names of the blocks and samplers this entry point uses.
            for (handle, glsl) in &reflection.uniforms {
                let var = &module.global_variables[*handle];
                if let Some(rb) = &var.binding
                    && let Some(b) = bindings
                        .iter_mut()
                        .find(|b| (b.group, b.binding) == (rb.group, rb.binding))
                {
                    b.glsl_name = Some(glsl.clone());
                }
            }
            for (glsl, mapping) in &reflection.texture_mapping {
                let var = &module.global_variables[mapping.texture];
                if let Some(rb) = &var.binding
                    && let Some(b) = bindings
                        .iter_mut()
                        .find(|b| (b.group, b.binding) == (rb.group, rb.binding))
                {
                    b.glsl_name = Some(glsl.clone());
                }
            }
            let es = if language == Language::GlslEs {
                ".es"
            } else {
                ""
            };
            files.push(ExportFile {
                file_name: format!("{}.{}.{}{es}.glsl", self.name, ep.name, ep.stage.suffix()),
                entry_point: Some(ep.name.to_owned()),
                stage: Some(ep.stage),
                code: Code::Text(text),
            });
        }
        for b in bindings.iter_mut() {
            b.glsl_binding = if explicit {
                numbers.get(&(b.group, b.binding)).copied()
            } else {
                None
            };
        }
        Ok(files)
    }
}
