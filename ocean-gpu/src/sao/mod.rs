//! Scalable Ambient Obscurance (McGuire, Mara & Luebke, HPG 2012) on the GPU: the twin of
//! [`ocean_sao::Sao`], whose CPU passes are its oracle.
//!
//! [`SaoPass`] reads the caller's depth texture (the depth buffer of a depth prepass, guard band
//! included) and writes an `r32float` obscurance texture of the output size (the input inset by
//! the guard band) that the caller's lighting reads with `textureLoad`, multiplying its ambient
//! (environment) light by A. Five passes, one compute pass each, 8 × 8 invocations per
//! workgroup:
//!
//! | pass | shader | over | writes |
//! |---|---|---|---|
//! | [`SaoStage::Z`] | `sao_z` | input | z level 0, `r32float` (Eq. 2) |
//! | [`SaoStage::Mips`] | `sao_mip` | level m + 1, one dispatch per level | z level m + 1 (Table 1) |
//! | [`SaoStage::Ao`] | `sao_ao` | output | packed A and depth key, `r32uint` (Eq. 1, 3–10, appendix; quad bilateral) |
//! | [`SaoStage::BlurHorizontal`] | `sao_blur` | output | packed, `r32uint` (§2.4) |
//! | [`SaoStage::BlurVertical`] | `sao_blur` | output | A, `r32float` (§2.4) |
//!
//! Every constant comes from [`ocean_sao::SaoUniforms`], computed on the host as the CPU
//! computes it, and every shader follows the CPU's operations in order (the WGSL names the CPU
//! function it mirrors): integer semantics included (`i32()` truncates the tap offsets toward
//! zero as Rust's `as` does, Eq. 9's `⌊log₂⌋` is the highest set bit of the truncated radius in
//! pixels, Eq. 8's hash is `u32` arithmetic with explicit parentheses around `^` and reduced
//! modulo 2π before any sine, which comes from ocean-core's `sincos` ported to WGSL). What
//! remains between the two sides is rounding a GPU may do differently (a fused multiply-add, a
//! division not correctly rounded): it moves a tap across a pixel boundary or a quantisation
//! step now and then, which the parity tests (`tests/tests/gpu_sao.rs`) bound.
//!
//! Within WebGPU's defaults: at most 3 storage textures per stage (the sample pass's debug
//! entry point; 1 otherwise), `r32float` and `r32uint` storage formats, 14 sampled textures in
//! the sample pass (one per z level; see `shaders/sao_mip.wgsl` for why the levels are separate
//! textures). The packed texels are the four bytes an RGBA8 texel would hold (the paper packs
//! into RGB8; WebGPU has no RGB8 storage format), as one `r32uint` word, so packing and
//! unpacking are exact integer operations.
//!
//! Textures and bind groups are made for one input size, guard band and level count, and made
//! again only when these change; the bind group of the caller's depth texture is kept while the
//! same texture comes back.
//!
//! The input (guard band included) must fit the device's `max_texture_dimension_2d`: 2048 px
//! under the downlevel limits of [`GpuContext::headless`], too few for 1920 × 1080 with a
//! 192 px guard band (2304 × 1464 px). A renderer's own device usually has the adapter's limit
//! (8192 px or more); `ocean bench sao` asks for it.

mod resources;
mod timer;

use ocean_sao::gpu_params::check_depth;
use ocean_sao::pack::Texel;
use ocean_sao::{Sao, SaoUniforms};

use crate::readback::{GpuTimer, read_texture};
use crate::{GpuContext, GpuError};
use resources::{Pipelines, TargetKey, Targets, check_depth_texture, check_limits, groups};

pub use resources::DEPTH_FORMATS;
pub use timer::{SaoStage, SaoTimer, SaoTimes};

/// One z level read back.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuZLevel {
    /// Width in texels.
    pub width: usize,
    /// Height in texels.
    pub height: usize,
    /// Camera-space z, row-major.
    pub z: Vec<f32>,
}

/// Every intermediate image of one GPU run, laid out as [`ocean_sao::Stages`] for comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct SaoStages {
    /// The z levels, level 0 (input size) first.
    pub levels: Vec<GpuZLevel>,
    /// The raw sample-pass obscurance (output size).
    pub raw: Vec<f32>,
    /// After the 2×2 quad bilateral.
    pub quad: Vec<f32>,
    /// Packed A and depth key (§2.3).
    pub packed: Vec<Texel>,
    /// After the horizontal blur.
    pub horizontal: Vec<Texel>,
    /// The final A.
    pub ao: Vec<f32>,
}

/// The SAO passes on the caller's device (see the [module documentation](self)).
#[derive(Debug)]
pub struct SaoPass {
    pipelines: Pipelines,
    uniform: wgpu::Buffer,
    targets: Option<Targets>,
    /// The `R32Float` depth texture that [`SaoPass::evaluate`] uploads into.
    upload: Option<wgpu::Texture>,
}

impl SaoPass {
    /// Builds the pipelines on `ctx`'s device (textures come with the first
    /// [`encode`](Self::encode)).
    ///
    /// # Errors
    ///
    /// [`GpuError::Wgpu`] when the device refuses a shader or pipeline.
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let device = ctx.device();
        let pipelines = Pipelines::new(device)?;
        let uniform = crate::scoped(device, || {
            Ok(device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("ocean sao params"),
                size: std::mem::size_of::<SaoUniforms>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }))
        })?;
        Ok(Self {
            pipelines,
            uniform,
            targets: None,
            upload: None,
        })
    }

    /// Checks `depth` and the device's limits against `sao`, (re)makes the textures when the
    /// size changed, writes the parameters and returns the z pass's bind group.
    fn prepare(
        &mut self,
        ctx: &GpuContext,
        sao: &Sao,
        depth: &wgpu::Texture,
    ) -> Result<wgpu::BindGroup, GpuError> {
        let device = ctx.device();
        let u = SaoUniforms::new(sao);
        check_limits(device, &u)?;
        check_depth_texture(depth, (u.input_size[0], u.input_size[1]))?;
        let key = TargetKey::new(&u);
        if self.targets.as_ref().is_none_or(|t| t.key != key) {
            // The old textures go first (both sets never hold memory at once), and nothing is
            // kept when making the new ones fails.
            self.targets = None;
            let made = crate::scoped(device, || {
                Ok(Targets::new(device, &self.pipelines, &self.uniform, key))
            })?;
            self.targets = Some(made);
        }
        let targets = self.targets.as_mut().ok_or(GpuError::NotConfigured {
            what: "SAO textures",
            call: "SaoPass::encode",
        })?;
        let group = match targets.cached_depth_group(depth) {
            Some(g) => g,
            None => {
                let g = crate::scoped(device, || {
                    Ok(targets.make_depth_group(device, &self.pipelines, &self.uniform, depth))
                })?;
                targets.depth = Some((depth.clone(), g.clone()));
                g
            }
        };
        crate::scoped(device, || {
            ctx.queue()
                .write_buffer(&self.uniform, 0, bytemuck::bytes_of(&u));
            Ok(())
        })?;
        Ok(group)
    }

    /// Records the five passes into the caller's `encoder`: `depth` (input size: the
    /// viewport's input, guard band included; one of [`DEPTH_FORMATS`] with
    /// `TEXTURE_BINDING` usage) in, the obscurance ([`SaoPass::ao_texture`]) out. `timer`, if
    /// given, timestamps each pass (call [`SaoTimer::resolve`] on the encoder afterwards).
    ///
    /// The parameters go into the pass's uniform buffer by `Queue::write_buffer`, so they reach
    /// the GPU with the caller's next `Queue::submit`: submit between two `encode` calls with
    /// different [`Sao`] set-ups (both would run with the second's parameters otherwise).
    ///
    /// The depth values are not checked (a shader cannot report them): they must lie in the
    /// convention's range, as a rasteriser writes them ([`SaoPass::evaluate`] checks a slice).
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidResource`] for a depth texture of another size, format, dimension,
    /// sample count or usage; [`GpuError::TooLarge`] for an input beyond the device's
    /// `max_texture_dimension_2d`; [`GpuError::Wgpu`]. Nothing is recorded on error.
    pub fn encode(
        &mut self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        sao: &Sao,
        depth: &wgpu::Texture,
        timer: Option<&SaoTimer>,
    ) -> Result<(), GpuError> {
        let z_group = self.prepare(ctx, sao, depth)?;
        crate::scoped(ctx.device(), || {
            for stage in SaoStage::ALL {
                self.record(
                    encoder,
                    stage,
                    &z_group,
                    timer.map(|t| t.stage(stage)),
                    false,
                )?;
            }
            Ok(())
        })
    }

    /// Records one pass only, reading what the earlier passes left in the pass's textures (so
    /// the passes can be submitted and timed one by one where the adapter has no timestamps).
    /// `timer`, if given, timestamps it (call [`GpuTimer::resolve`] afterwards).
    ///
    /// # Errors
    ///
    /// As [`encode`](Self::encode).
    pub fn encode_stage(
        &mut self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        sao: &Sao,
        depth: &wgpu::Texture,
        stage: SaoStage,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        let z_group = self.prepare(ctx, sao, depth)?;
        crate::scoped(ctx.device(), || {
            self.record(encoder, stage, &z_group, timer, false)
        })
    }

    /// Records `stage` as one compute pass (call inside [`crate::scoped`]). `with_stages`
    /// selects the sample pass entry point that also writes the raw and quad-filtered A.
    fn record(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stage: SaoStage,
        z_group: &wgpu::BindGroup,
        timer: Option<&GpuTimer>,
        with_stages: bool,
    ) -> Result<(), GpuError> {
        let t = self.targets.as_ref().ok_or(GpuError::NotConfigured {
            what: "SAO textures",
            call: "SaoPass::encode",
        })?;
        let p = &self.pipelines;
        let key = t.key;
        if stage == SaoStage::Mips && key.levels == 1 && timer.is_none() {
            // max_mip = 0: no level to make (an empty pass is still recorded when timed, so
            // that its timestamps exist).
            return Ok(());
        }
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(stage.name()),
            timestamp_writes: timer.map(GpuTimer::compute_pass_writes),
        });
        let mut dispatch = |pipeline: &wgpu::ComputePipeline, group: &wgpu::BindGroup, size| {
            let (gx, gy) = groups(size);
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, group, &[]);
            pass.dispatch_workgroups(gx, gy, 1);
        };
        match stage {
            SaoStage::Z => dispatch(&p.z, z_group, key.input),
            SaoStage::Mips => {
                for (m, group) in t.mip_groups.iter().enumerate() {
                    dispatch(&p.mip, group, key.level_size(m as u32 + 1));
                }
            }
            SaoStage::Ao => match (&t.stages, with_stages) {
                (Some(s), true) => dispatch(&p.ao_stages, &s.group, key.output),
                _ => dispatch(&p.ao, &t.ao_group, key.output),
            },
            SaoStage::BlurHorizontal => dispatch(&p.blur_h, &t.blur_h_group, key.output),
            SaoStage::BlurVertical => dispatch(&p.blur_v, &t.blur_v_group, key.output),
        }
        Ok(())
    }

    /// The obscurance texture (`r32float`, the viewport's output size, `TEXTURE_BINDING |
    /// STORAGE_BINDING | COPY_SRC`), once [`encode`](Self::encode) has made it. It is made again
    /// when the size changes: fetch it after each `encode` that may change the size.
    pub fn ao_texture(&self) -> Option<&wgpu::Texture> {
        self.targets.as_ref().map(|t| &t.ao)
    }

    /// A view of [`SaoPass::ao_texture`].
    pub fn ao_view(&self) -> Option<&wgpu::TextureView> {
        self.targets.as_ref().map(|t| &t.ao_view)
    }

    /// Uploads `depth` (the viewport's input size, row-major, row 0 at the top) into the pass's
    /// own `R32Float` texture after the CPU's checks, runs every pass and waits. `with_stages`
    /// as in [`SaoPass::record`].
    fn run_slice(
        &mut self,
        ctx: &GpuContext,
        sao: &Sao,
        depth: &[f32],
        with_stages: bool,
    ) -> Result<(), GpuError> {
        check_depth(sao.z_constants(), sao.viewport(), depth)?;
        let vp = sao.viewport();
        let (w, h) = (vp.input_width() as u32, vp.input_height() as u32);
        let device = ctx.device();
        // The limits first: the upload texture must not be made beyond them.
        check_limits(device, &SaoUniforms::new(sao))?;
        let upload = crate::scoped(device, || {
            let upload = match &self.upload {
                Some(t) if (t.width(), t.height()) == (w, h) => t.clone(),
                _ => device.create_texture(&wgpu::TextureDescriptor {
                    label: Some("ocean sao depth upload"),
                    size: wgpu::Extent3d {
                        width: w,
                        height: h,
                        depth_or_array_layers: 1,
                    },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format: wgpu::TextureFormat::R32Float,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                    view_formats: &[],
                }),
            };
            ctx.queue().write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &upload,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                bytemuck::cast_slice(depth),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4 * w),
                    rows_per_image: Some(h),
                },
                upload.size(),
            );
            Ok(upload)
        })?;
        self.upload = Some(upload.clone());
        let z_group = self.prepare(ctx, sao, &upload)?;
        if with_stages
            && let Some(t) = &mut self.targets
            && t.stages.is_none()
        {
            let made = crate::scoped(device, || {
                Ok(t.make_stages(device, &self.pipelines, &self.uniform))
            })?;
            t.stages = Some(made);
        }
        crate::scoped(device, || {
            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean sao evaluate"),
            });
            for stage in SaoStage::ALL {
                self.record(&mut encoder, stage, &z_group, None, with_stages)?;
            }
            ctx.queue().submit([encoder.finish()]);
            Ok(())
        })
    }

    /// Runs every pass on `depth` (the viewport's input size, row-major, row 0 at the top) and
    /// reads the final A back (output size, row-major): the one-off form of
    /// [`encode`](Self::encode) for tests and tools, the GPU twin of [`Sao::run`].
    ///
    /// # Errors
    ///
    /// [`GpuError::Sao`] for a depth slice of the wrong length or with a value that is not
    /// finite or outside the convention's range (the errors of `Sao::run`, first offending
    /// pixel); [`GpuError::TooLarge`]; [`GpuError::Wgpu`].
    pub fn evaluate(
        &mut self,
        ctx: &GpuContext,
        sao: &Sao,
        depth: &[f32],
    ) -> Result<Vec<f32>, GpuError> {
        self.run_slice(ctx, sao, depth, false)?;
        let t = self.targets.as_ref().ok_or(GpuError::NotConfigured {
            what: "SAO textures",
            call: "SaoPass::encode",
        })?;
        read_f32(ctx, &t.ao)
    }

    /// [`evaluate`](Self::evaluate) keeping every intermediate image: the GPU twin of
    /// [`Sao::stages`].
    ///
    /// # Errors
    ///
    /// As [`evaluate`](Self::evaluate).
    pub fn evaluate_stages(
        &mut self,
        ctx: &GpuContext,
        sao: &Sao,
        depth: &[f32],
    ) -> Result<SaoStages, GpuError> {
        self.run_slice(ctx, sao, depth, true)?;
        let not_made = GpuError::NotConfigured {
            what: "SAO textures",
            call: "SaoPass::encode",
        };
        let t = self.targets.as_ref().ok_or(not_made)?;
        let s = t.stages.as_ref().ok_or(GpuError::NotConfigured {
            what: "SAO stage textures",
            call: "SaoPass::evaluate_stages",
        })?;
        let mut levels = Vec::with_capacity(t.levels.len());
        for level in &t.levels {
            levels.push(GpuZLevel {
                width: level.width() as usize,
                height: level.height() as usize,
                z: read_f32(ctx, level)?,
            });
        }
        Ok(SaoStages {
            levels,
            raw: read_f32(ctx, &s.raw)?,
            quad: read_f32(ctx, &s.quad)?,
            packed: read_texels(ctx, &t.packed)?,
            horizontal: read_texels(ctx, &t.horizontal)?,
            ao: read_f32(ctx, &t.ao)?,
        })
    }
}

fn read_f32(ctx: &GpuContext, texture: &wgpu::Texture) -> Result<Vec<f32>, GpuError> {
    Ok(bytemuck::pod_collect_to_vec(
        &read_texture(ctx, texture, 0)?.data,
    ))
}

/// An `r32uint` texture of packed texels: each word's little-endian bytes are the texel.
fn read_texels(ctx: &GpuContext, texture: &wgpu::Texture) -> Result<Vec<Texel>, GpuError> {
    let words: Vec<u32> = bytemuck::pod_collect_to_vec(&read_texture(ctx, texture, 0)?.data);
    Ok(words.iter().map(|w| w.to_le_bytes()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shaders;

    /// The WGSL `Params` block has the members and offsets of `SaoUniforms`, in every SAO
    /// shader.
    #[test]
    fn params_match_the_wgsl_layout() {
        use std::mem::offset_of;
        let expected = [
            ("z_c", offset_of!(SaoUniforms, z_c)),
            ("scale", offset_of!(SaoUniforms, scale)),
            ("offset", offset_of!(SaoUniforms, offset)),
            ("input_size", offset_of!(SaoUniforms, input_size)),
            ("output_size", offset_of!(SaoUniforms, output_size)),
            ("guard", offset_of!(SaoUniforms, guard)),
            ("perspective", offset_of!(SaoUniforms, perspective)),
            ("far_depth", offset_of!(SaoUniforms, far_depth)),
            ("mip_origin", offset_of!(SaoUniforms, mip_origin)),
            ("radius_pixels", offset_of!(SaoUniforms, radius_pixels)),
            ("radius2", offset_of!(SaoUniforms, radius2)),
            ("inv_radius2", offset_of!(SaoUniforms, inv_radius2)),
            ("epsilon", offset_of!(SaoUniforms, epsilon)),
            ("samples", offset_of!(SaoUniforms, samples)),
            ("inv_samples", offset_of!(SaoUniforms, inv_samples)),
            ("two_pi_turns", offset_of!(SaoUniforms, two_pi_turns)),
            ("mip_switch_log2", offset_of!(SaoUniforms, mip_switch_log2)),
            ("max_mip", offset_of!(SaoUniforms, max_mip)),
            ("mip_filter", offset_of!(SaoUniforms, mip_filter)),
            ("estimator", offset_of!(SaoUniforms, estimator)),
            ("strength", offset_of!(SaoUniforms, strength)),
            ("beta", offset_of!(SaoUniforms, beta)),
            ("k", offset_of!(SaoUniforms, k)),
            ("normal_limit", offset_of!(SaoUniforms, normal_limit)),
            ("quad_threshold", offset_of!(SaoUniforms, quad_threshold)),
            (
                "normal_rejection",
                offset_of!(SaoUniforms, normal_rejection),
            ),
            ("quad_filter", offset_of!(SaoUniforms, quad_filter)),
            ("inv_z_min", offset_of!(SaoUniforms, inv_z_min)),
            ("blur_radius", offset_of!(SaoUniforms, blur_radius)),
            ("blur_stride", offset_of!(SaoUniforms, blur_stride)),
            ("depth_scale", offset_of!(SaoUniforms, depth_scale)),
            ("blur_plane", offset_of!(SaoUniforms, blur_plane)),
            ("normals_nearest", offset_of!(SaoUniforms, normals_nearest)),
            ("inv_blur_extent", offset_of!(SaoUniforms, inv_blur_extent)),
            ("z_min", offset_of!(SaoUniforms, z_min)),
            ("_pad0", offset_of!(SaoUniforms, _pad0)),
            ("_pad1", offset_of!(SaoUniforms, _pad1)),
            ("gauss", offset_of!(SaoUniforms, gauss)),
        ];
        for name in ["sao_z", "sao_mip", "sao_ao", "sao_blur"] {
            let b = shaders::get(name).unwrap().bindings().unwrap();
            assert_eq!(b[0].name, "params", "{name}");
            assert_eq!(
                b[0].size as usize,
                std::mem::size_of::<SaoUniforms>(),
                "{name}"
            );
            let got: Vec<(&str, usize)> = b[0]
                .members
                .iter()
                .map(|m| (m.name.as_str(), m.offset as usize))
                .collect();
            assert_eq!(got, expected, "{name}");
        }
    }

    fn wgsl_f32(module: &naga::Module, name: &str) -> f32 {
        let (_, c) = module
            .constants
            .iter()
            .find(|(_, c)| c.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("WGSL constant {name}"));
        match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::F32(v)) => v,
            ref other => panic!("{name} is {other:?}"),
        }
    }

    /// The WGSL literals round to exactly the CPU's `f32` constants.
    #[test]
    fn wgsl_constants_are_the_cpu_constants() {
        use std::f64::consts::TAU;
        let (ao, _) = shaders::get("sao_ao").unwrap().module().unwrap();
        let turns = ocean_sao::spiral::HASH_BYTE_TURNS;
        for (k, t) in turns.iter().enumerate() {
            let v = wgsl_f32(&ao, &format!("HASH_BYTE_TURN_{k}"));
            assert_eq!(v.to_bits(), t.to_bits(), "HASH_BYTE_TURN_{k}");
        }
        assert_eq!(wgsl_f32(&ao, "TWO_PI").to_bits(), (TAU as f32).to_bits());
        assert_eq!(
            wgsl_f32(&ao, "INV_TWO_PI").to_bits(),
            ((1.0 / TAU) as f32).to_bits()
        );
        assert_eq!(
            wgsl_f32(&ao, "FRAC_2_PI").to_bits(),
            std::f32::consts::FRAC_2_PI.to_bits()
        );
        for name in ["sao_z", "sao_mip", "sao_ao", "sao_blur"] {
            let (m, _) = shaders::get(name).unwrap().module().unwrap();
            assert_eq!(
                wgsl_f32(&m, "SKY_Z").to_bits(),
                ocean_sao::SKY_Z.to_bits(),
                "{name}"
            );
        }
    }

    /// The WGSL port of ocean-core's `sincos` uses its constants: rebuilt here from the WGSL
    /// literals, the CPU algorithm returns ocean-core's bits (the polynomial coefficients and
    /// the three-part π/2 are private to ocean-core, so they are checked through the result).
    #[test]
    fn wgsl_sincos_constants_reproduce_ocean_core() {
        let (ao, _) = shaders::get("sao_ao").unwrap().module().unwrap();
        let c = |n: &str| wgsl_f32(&ao, n);
        let (hi, mid, lo) = (c("PIO2_HI"), c("PIO2_MID"), c("PIO2_LO"));
        let (s1, s2, s3) = (c("S1"), c("S2"), c("S3"));
        let (c1, c2, c3) = (c("C1"), c("C2"), c("C3"));
        let frac = c("FRAC_2_PI");
        let port = |x: f32| {
            let q = (x * frac).round_ties_even();
            let r = ((x - q * hi) - q * mid) - q * lo;
            let z = r * r;
            let s = ((s3 * z + s2) * z + s1) * z * r + r;
            let co = ((c3 * z + c2) * z + c1) * z * z - 0.5 * z + 1.0;
            let qi = q as i32;
            let (mut sn, mut cs) = if qi & 1 != 0 { (co, s) } else { (s, co) };
            if qi & 2 != 0 {
                sn = -sn;
            }
            if (qi + 1) & 2 != 0 {
                cs = -cs;
            }
            (sn, cs)
        };
        // The sample pass's angles: θ = α·2πτ + φ with α < 1, τ ≤ 1000, φ < 2π.
        for i in 0..200_000 {
            let x = i as f32 * 3.7e-4 - 3.0;
            let (s, co) = ocean_core::sincos::sincos(x);
            let (ps, pc) = port(x);
            assert_eq!(
                (ps.to_bits(), pc.to_bits()),
                (s.to_bits(), co.to_bits()),
                "{x}"
            );
        }
    }
}
