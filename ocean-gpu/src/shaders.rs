//! Every WGSL source of the crate, validated by naga and exportable to other shading languages.
//!
//! An OpenGL, Vulkan, D3D or Metal engine that does not use wgpu can still run the ocean passes:
//! [`export`] translates a shader with naga and lists its resource bindings, so the engine can
//! create matching buffers and bind them.
//!
//! | [`Language`]        | output                                   | versions                       |
//! |---------------------|------------------------------------------|--------------------------------|
//! | [`Language::Glsl`]  | one file per entry point                 | 430 core (compute), 330 core (draw) |
//! | [`Language::GlslEs`]| one file per entry point                 | ES 3.10                        |
//! | [`Language::Hlsl`]  | one file, every entry point              | Shader Model 5.1               |
//! | [`Language::Msl`]   | one file, every entry point              | MSL 2.0                        |
//! | [`Language::SpirV`] | one binary module, every entry point     | SPIR-V 1.0                     |
//!
//! Bindings: WGSL `@group(g) @binding(b)` stays `set = g, binding = b` in SPIR-V,
//! `register(<b|t|u|s>b, space g)` in HLSL. In GLSL the groups are flattened: each namespace
//! (uniform blocks, shader storage blocks, texture units, image units) is numbered from 0 in
//! (group, binding) order; [`Binding::glsl_binding`] gives the number and [`Binding::glsl_name`]
//! the block or sampler name naga gave it. GLSL 3.30 has no `binding =` qualifier, so there the
//! engine assigns the number itself (`glUniformBlockBinding`, `glUniform1i`) by that name.
//! MSL resources are numbered per kind (`[[buffer(n)]]`, `[[texture(n)]]`) by naga's defaults.

use std::collections::BTreeMap;
use std::fmt;
use std::str::FromStr;

use naga::common::wgsl::TypeContext;
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};

/// Whether a shader is a compute pass or a draw (vertex + fragment) pass. It selects the GLSL
/// version: 4.30 core for compute (the first desktop version with compute shaders and storage
/// blocks), 3.30 core for draw passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShaderKind {
    /// Compute shader entry points only.
    Compute,
    /// Vertex and fragment entry points.
    Draw,
}

/// A pipeline stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Stage {
    /// Vertex shader.
    Vertex,
    /// Fragment shader.
    Fragment,
    /// Compute shader.
    Compute,
}

impl Stage {
    fn to_naga(self) -> naga::ShaderStage {
        match self {
            Stage::Vertex => naga::ShaderStage::Vertex,
            Stage::Fragment => naga::ShaderStage::Fragment,
            Stage::Compute => naga::ShaderStage::Compute,
        }
    }

    /// The conventional file-name suffix: `vert`, `frag` or `comp`.
    pub fn suffix(self) -> &'static str {
        match self {
            Stage::Vertex => "vert",
            Stage::Fragment => "frag",
            Stage::Compute => "comp",
        }
    }
}

/// An entry point of a registered shader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EntryPoint {
    /// Function name in the WGSL source.
    pub name: &'static str,
    /// Its stage.
    pub stage: Stage,
}

/// A WGSL shader of the crate.
#[derive(Clone, Copy, Debug)]
pub struct ShaderEntry {
    /// Registry name, also the stem of exported file names.
    pub name: &'static str,
    /// The WGSL files it is assembled from, in order (shared snippets first).
    pub files: &'static [&'static str],
    /// The complete WGSL source (the files concatenated).
    pub source: &'static str,
    /// Compute or draw.
    pub kind: ShaderKind,
    /// Entry points, as declared in the source.
    pub entry_points: &'static [EntryPoint],
    /// One line on what it computes.
    pub description: &'static str,
}

/// Shader capabilities the passes may use: none beyond core WGSL. wgpu enables extra
/// capabilities only for optional device features, and this crate requests none that affect
/// shaders, so validating with the empty set proves the sources run on every device the crate
/// accepts (and in browsers).
pub const CAPABILITIES: Capabilities = Capabilities::empty();

/// Every registered shader.
pub fn all() -> &'static [ShaderEntry] {
    &SHADERS
}

/// The shader called `name`, if any.
pub fn get(name: &str) -> Option<&'static ShaderEntry> {
    SHADERS.iter().find(|s| s.name == name)
}

/// Why a shader could not be found, parsed, validated or translated.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ShaderError {
    /// No shader has that name.
    #[error("no shader named {name:?} (available: {available})")]
    UnknownShader {
        /// The requested name.
        name: String,
        /// The registered names, comma-separated.
        available: String,
    },
    /// Unknown language name.
    #[error("unknown shader language {0:?} (expected glsl, glsles, hlsl, msl or spirv)")]
    UnknownLanguage(String),
    /// The WGSL does not parse.
    #[error("shader {name}: WGSL parse error:\n{message}")]
    Parse {
        /// Shader name.
        name: &'static str,
        /// naga's report, with source excerpts.
        message: String,
    },
    /// The WGSL parses but does not validate.
    #[error("shader {name}: validation error:\n{message}")]
    Validation {
        /// Shader name.
        name: &'static str,
        /// naga's report, with source excerpts.
        message: String,
    },
    /// naga could not translate it to the requested language.
    #[error("shader {name}: {language} translation failed: {message}")]
    Translation {
        /// Shader name.
        name: &'static str,
        /// Target language.
        language: Language,
        /// naga's error.
        message: String,
    },
}

impl ShaderEntry {
    /// Parses and validates the source with [`ValidationFlags::all`] and [`CAPABILITIES`].
    pub fn module(&self) -> Result<(naga::Module, ModuleInfo), ShaderError> {
        let module = naga::front::wgsl::parse_str(self.source).map_err(|e| ShaderError::Parse {
            name: self.name,
            message: e.emit_to_string(self.source),
        })?;
        let info = Validator::new(ValidationFlags::all(), CAPABILITIES)
            .validate(&module)
            .map_err(|e| ShaderError::Validation {
                name: self.name,
                message: e.emit_to_string(self.source),
            })?;
        Ok((module, info))
    }

    /// The shader's resource bindings, in (group, binding) order (GLSL fields unset).
    pub fn bindings(&self) -> Result<Vec<Binding>, ShaderError> {
        let (module, _) = self.module()?;
        Ok(bindings_of(&module))
    }
}

mod export;
mod registry;

pub use export::*;
pub use registry::*;

#[cfg(test)]
mod tests;
