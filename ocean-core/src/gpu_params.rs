//! The uniform blocks and descriptors of the GPU twins of this crate's grid evaluations
//! (`ocean-gpu`'s `trochoid.wgsl` for [`crate::WaveSet::evaluate_grid`], `layers.wgsl` for
//! [`crate::evaluate_layers`]), defined here beside the math they encode so that the WGSL, the
//! pass that fills them and any engine binding the exported shaders share one layout.
//!
//! Each is `#[repr(C)]`, every member 4 bytes, padded explicitly to whole 16-byte rows: the same
//! under std140 and std430, and `Pod` (no implicit padding). `ocean-gpu`'s shader tests check
//! every member's offset against the WGSL structs.

/// The pass's uniform block, byte for byte the WGSL `Params` struct (32 bytes, std140).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TrochoidParams {
    /// Columns (along x).
    pub nx: u32,
    /// Rows (along z).
    pub nz: u32,
    /// Number of waves.
    pub waves: u32,
    /// Index in the sin/cos table buffer of the first column entry: `waves · nz`.
    pub cols_offset: u32,
    /// Workgroups along x of the dispatch; the linear workgroup index is
    /// `workgroup_id.y · groups_x + workgroup_id.x`.
    pub groups_x: u32,
    /// Explicit padding, 0: keeps the struct at 32 bytes (a whole number of 16-byte std140
    /// rows) with no implicit padding, which `Pod` forbids.
    pub _pad: u32,
    /// Grid spacing along x, metres (`f32`, as the CPU kernel rounds it).
    pub spacing_x: f32,
    /// Grid spacing along z, metres.
    pub spacing_z: f32,
}

/// The pass's uniform block, byte for byte the WGSL `Params` struct of `layers.wgsl`
/// (32 bytes, std140).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LayersParams {
    /// Grid columns (along x).
    pub nx: u32,
    /// Grid rows (along z).
    pub nz: u32,
    /// Number of [`LayerDesc`]s.
    pub layers: u32,
    /// Workgroups along x of the dispatch; the linear workgroup index is
    /// `workgroup_id.y · groups_x + workgroup_id.x`.
    pub groups_x: u32,
    /// 1 when a height field is given (at word `height` of `data`), else 0.
    pub has_height: u32,
    /// Word offset in `data` of the height field (0 without one).
    pub height: u32,
    /// Grid spacing along x, metres (`f32`, as the CPU kernel rounds it).
    pub spacing_x: f32,
    /// Grid spacing along z, metres.
    pub spacing_z: f32,
}

/// One layer as the shader sees it, byte for byte the WGSL `LayerDesc` (48 bytes). Offsets are
/// in `f32` words of the `data` buffer.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LayerDesc {
    /// First grid column of the rectangle.
    pub i0: u32,
    /// First grid row of the rectangle.
    pub j0: u32,
    /// Columns of the rectangle.
    pub nx: u32,
    /// Rows of the rectangle.
    pub nz: u32,
    /// Number of waves.
    pub waves: u32,
    /// Wave `w`'s [`crate::WaveCoeffs`] at words `coeffs + 8w ..= coeffs + 8w + 7`.
    pub coeffs: u32,
    /// `[sin R, cos R]` of wave `w` at rectangle row `r` (grid row `j0 + r`) at word
    /// `rows + 2(w · nz + r)`.
    pub rows: u32,
    /// `[sin C, cos C]` of wave `w` at rectangle column `c` (grid column `i0 + c`) at word
    /// `cols + 2(w · nx + c)`.
    pub cols: u32,
    /// `[m cos φ, m sin φ]` at rectangle point (c, r) at word `modulation + 2(r · nx + c)`.
    pub modulation: u32,
    /// Explicit padding, 0 (the struct is a whole number of 16-byte rows).
    pub _pad: [u32; 3],
}
