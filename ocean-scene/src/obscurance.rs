//! The obscurance of `ocean render`: Scalable Ambient Obscurance (McGuire, Mara & Luebke 2012,
//! `ocean_gpu::SaoPass`) over the frame's whole depth buffer (sea, island and rocks). Its A
//! scales the frame's ambient light alone (`OceanRenderer::compose`: `direct + A · ambient`),
//! which darkens the water where it meets the rocks, the island and the pier, the terrain's
//! creases, and the shade under the pier's deck, while sunlit surfaces keep their direct light.

use crate::SceneError;
use crate::check::range;
use ocean_core::Camera;
use ocean_gpu::{GpuContext, GpuError, SaoPass, wgpu};
use ocean_sao::{DepthSource, Estimator, Sao, SaoParams, Viewport};
use serde::Deserialize;

/// `[obscurance]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct ObscuranceSection {
    /// Whether the pass runs.
    pub enabled: bool,
    /// World-space radius of the sampled ball, metres (the paper's r).
    pub radius: f64,
    /// Samples per pixel (the paper: 9).
    pub samples: u32,
    /// Intensity of the appendix's falloff estimator (1: the paper's formula).
    pub intensity: f64,
}

impl Default for ObscuranceSection {
    fn default() -> Self {
        Self {
            enabled: true,
            radius: 2.0,
            samples: 9,
            intensity: 1.0,
        }
    }
}

impl ObscuranceSection {
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        range("obscurance.radius", self.radius, 1e-3, 1e3)?;
        range("obscurance.samples", f64::from(self.samples), 1.0, 64.0)?;
        range("obscurance.intensity", self.intensity, 0.0, 10.0)
    }
}

/// The obscurance of every frame: SAO's passes when enabled, else a texture of ones.
pub enum Obscurance {
    Sao {
        pass: Box<SaoPass>,
        sao: Box<Sao>,
    },
    /// A = 1 everywhere (R32Float, the frame's size).
    Off(wgpu::TextureView),
}

impl Obscurance {
    /// For `camera`'s projection (it must not change between frames) over a `width × height`
    /// depth buffer.
    ///
    /// # Errors
    ///
    /// A message for parameters SAO refuses or a device error.
    pub fn new(
        ctx: &GpuContext,
        section: &ObscuranceSection,
        camera: &Camera,
        size: (u32, u32),
    ) -> Result<Self, SceneError> {
        if !section.enabled {
            return Ok(Self::Off(ones(ctx, size)));
        }
        let params = SaoParams {
            radius: section.radius as f32,
            samples: section.samples,
            spiral_turns: ocean_sao::spiral::default_spiral_turns(section.samples) as f32,
            estimator: match Estimator::FALLOFF {
                Estimator::Falloff { beta, .. } => Estimator::Falloff {
                    beta,
                    intensity: section.intensity as f32,
                },
                other => other,
            },
            ..SaoParams::default()
        };
        let viewport = Viewport::new(size.0 as usize, size.1 as usize, 0)
            .map_err(|e| format!("obscurance: {e}"))?;
        let sao = Sao::from_camera(camera, DepthSource::Window, viewport, params)
            .map_err(|e| format!("obscurance: {e}"))?;
        let pass = SaoPass::new(ctx)?;
        Ok(Self::Sao {
            pass: Box::new(pass),
            sao: Box::new(sao),
        })
    }

    /// Records SAO over `depth` (`Depth32Float` with `TEXTURE_BINDING`) when enabled, and
    /// returns the view of A (`R32Float`, 1 = unoccluded) that the frame's composition reads.
    ///
    /// # Errors
    ///
    /// The SAO pass's errors (a depth texture of another size or usage).
    pub fn encode(
        &mut self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        depth: &wgpu::Texture,
    ) -> Result<&wgpu::TextureView, GpuError> {
        match self {
            Self::Sao { pass, sao } => {
                pass.encode(ctx, encoder, sao, depth, None)?;
                pass.ao_view().ok_or(GpuError::NotConfigured {
                    what: "SAO output",
                    call: "SaoPass::encode",
                })
            }
            Self::Off(view) => Ok(view),
        }
    }

    /// Whether SAO runs.
    pub fn enabled(&self) -> bool {
        matches!(self, Self::Sao { .. })
    }
}

/// An R32Float texture of ones.
fn ones(ctx: &GpuContext, size: (u32, u32)) -> wgpu::TextureView {
    use wgpu::util::DeviceExt;
    let texture = ctx.device().create_texture_with_data(
        ctx.queue(),
        &wgpu::TextureDescriptor {
            label: Some("no obscurance"),
            size: wgpu::Extent3d {
                width: size.0,
                height: size.1,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::R32Float,
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        bytemuck::cast_slice(&vec![1.0f32; size.0 as usize * size.1 as usize]),
    );
    texture.create_view(&wgpu::TextureViewDescriptor::default())
}
