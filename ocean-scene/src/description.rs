//! Scene files of `ocean render`: a TOML document (`scenes/default.toml` is the built-in scene
//! and the format's reference, every key commented there).
//!
//! Parsing is strict: an unknown key, a value of the wrong type or out of range is an error that
//! names the line and the key. [`SceneDescription`] mirrors the document; [`SceneDescription::camera`] and
//! [`SceneDescription::lighting`] turn it into the library's types.

use std::path::Path;

use glam::{DVec2, DVec3};
use ocean_brdf::{Lighting, SeaParams, SkyParams, SpectrumParams};
use ocean_core::{Camera, DepthConvention, Far, Projection};
use serde::Deserialize;

use crate::SceneError;
use crate::check::range;
use crate::island::{IslandSection, WaveBox};
use crate::obscurance::ObscuranceSection;
use crate::pier::PierSection;
use crate::rock_placement::Rock;

/// The built-in scene.
pub const DEFAULT_SCENE: &str = include_str!("../scenes/default.toml");

/// A scene file.
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct SceneDescription {
    pub render: RenderSection,
    pub camera: CameraSection,
    pub sun: SunSection,
    pub sky: SkySection,
    pub spectrum: SpectrumSection,
    /// `[island]`: absent for the open sea alone.
    pub island: Option<IslandSection>,
    /// `[[boxes]]`: the winds raising wave train boxes around the island.
    pub boxes: Vec<WaveBox>,
    pub rocks: Vec<Rock>,
    /// `[pier]`: absent for no pier.
    pub pier: Option<PierSection>,
    /// `[obscurance]`: ambient obscurance over the whole frame.
    pub obscurance: ObscuranceSection,
}

/// `[render]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct RenderSection {
    pub width: u32,
    pub height: u32,
    pub time: f64,
    pub fps: f64,
    /// Samples per pixel: 1, or `ocean_gpu::MSAA_SAMPLES` for antialiased edges.
    pub samples: u32,
}

impl Default for RenderSection {
    fn default() -> Self {
        Self {
            width: 1280,
            height: 720,
            time: 0.0,
            fps: 30.0,
            samples: ocean_gpu::MSAA_SAMPLES,
        }
    }
}

/// The camera presets of `[camera] preset` and `--camera`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "lowercase")]
pub enum Preset {
    /// 6 m above the water, looking 8° down.
    Shore,
    /// 4 m above the water, looking at the horizon.
    Horizon,
    /// 120 m up, looking 30° down.
    High,
    /// 10 m up, circling the point 40 m ahead once a minute of scene time, looking at it.
    Orbit,
}

/// `[camera]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct CameraSection {
    pub preset: Preset,
    pub eye: Option<[f64; 3]>,
    pub target: Option<[f64; 3]>,
    pub fov_y: f64,
    pub near: f64,
}

impl Default for CameraSection {
    fn default() -> Self {
        Self {
            preset: Preset::Shore,
            eye: None,
            target: None,
            fov_y: 55.0,
            near: 0.2,
        }
    }
}

/// `[sun]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct SunSection {
    pub elevation: f64,
    pub azimuth: f64,
    pub irradiance: [f64; 3],
}

impl Default for SunSection {
    fn default() -> Self {
        Self {
            elevation: 25.0,
            azimuth: 35.0,
            irradiance: [1.0, 0.96, 0.90],
        }
    }
}

/// `[sky]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct SkySection {
    pub zenith_radiance: [f64; 3],
}

impl Default for SkySection {
    fn default() -> Self {
        Self {
            zenith_radiance: [0.025, 0.045, 0.09],
        }
    }
}

/// `[spectrum]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct SpectrumSection {
    pub wind_speed: f64,
    pub wind_direction: f64,
    pub waves: usize,
    pub min_wavelength: f64,
    pub max_wavelength: f64,
    pub max_steepness: f64,
    pub seed: u64,
}

impl Default for SpectrumSection {
    fn default() -> Self {
        let p = SpectrumParams::default();
        Self {
            wind_speed: p.wind_speed,
            wind_direction: 0.0,
            waves: p.waves,
            min_wavelength: p.min_wavelength,
            max_wavelength: p.max_wavelength,
            max_steepness: p.max_steepness,
            seed: p.seed,
        }
    }
}

/// The point the presets look at and orbit: 40 m ahead of the origin along −z, at sea level.
const FOCUS: DVec3 = DVec3::new(0.0, 0.0, -40.0);
/// Seconds of scene time per revolution of the orbit preset.
const ORBIT_PERIOD: f64 = 60.0;

impl SceneDescription {
    /// Parses and checks a scene; `origin` names the document in messages.
    ///
    /// # Errors
    ///
    /// A message naming `origin`, the line and the key: TOML syntax, unknown keys, wrong types,
    /// values out of range.
    pub fn parse(text: &str, origin: &str) -> Result<Self, SceneError> {
        let scene: SceneDescription =
            toml::from_str(text).map_err(|e| format!("{origin}: {}", e.to_string().trim_end()))?;
        scene
            .check()
            .map_err(|(key, index, why)| match line_of(text, key, index) {
                Some(line) => format!("{origin}, line {line}: `{key}` {why}"),
                None => format!("{origin}: `{key}` {why}"),
            })?;
        Ok(scene)
    }

    /// Reads and parses a scene file.
    ///
    /// # Errors
    ///
    /// An unreadable file, or [`SceneDescription::parse`]'s errors.
    pub fn read(path: &Path) -> Result<Self, SceneError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read the scene {}: {e}", path.display()))?;
        Self::parse(&text, &path.display().to_string())
    }

    /// Checks the scene again after command-line overrides (`--width` and the like).
    ///
    /// # Errors
    ///
    /// The first value out of range, named as its key.
    pub fn check_overrides(&self) -> Result<(), SceneError> {
        self.check()
            .map_err(|(key, _, why)| SceneError::Description(format!("`{key}` {why}")))
    }

    /// The first key out of range, as `section.key` with the index of its table among the
    /// tables of that name (0 but for `[[rocks]]`), and why.
    fn check(&self) -> Result<(), (&'static str, usize, String)> {
        self.check_sections().map_err(|(key, why)| (key, 0, why))?;
        if let Some(island) = &self.island {
            island.check().map_err(|(key, why)| (key, 0, why))?;
        }
        self.obscurance
            .check()
            .map_err(|(key, why)| (key, 0, why))?;
        if let Some(pier) = &self.pier {
            pier.check().map_err(|(key, why)| (key, 0, why))?;
        }
        for (i, b) in self.boxes.iter().enumerate() {
            b.check()
                .map_err(|(key, why)| (key, i, format!("(box {}) {why}", i + 1)))?;
        }
        if !self.boxes.is_empty() && self.island.is_none() {
            return Err((
                "boxes.centre",
                0,
                "needs an [island] section: the boxes are computed on its grid".to_owned(),
            ));
        }
        for (i, r) in self.rocks.iter().enumerate() {
            r.check(self.island.as_ref())
                .map_err(|(key, why)| (key, i, format!("(rock {}) {why}", i + 1)))?;
        }
        Ok(())
    }

    fn check_sections(&self) -> Result<(), (&'static str, String)> {
        let r = &self.render;
        for (key, v) in [("render.width", r.width), ("render.height", r.height)] {
            if !(1..=8192).contains(&v) {
                return Err((key, format!("= {v} is outside 1 to 8192 pixels")));
            }
        }
        finite("render.time", r.time)?;
        range("render.fps", r.fps, 1e-3, 1e4)?;
        if r.samples != 1 && r.samples != ocean_gpu::MSAA_SAMPLES {
            return Err((
                "render.samples",
                format!(
                    "= {} is neither 1 nor {} (the sample counts every adapter renders)",
                    r.samples,
                    ocean_gpu::MSAA_SAMPLES
                ),
            ));
        }
        let c = &self.camera;
        range("camera.fov_y", c.fov_y, 1.0, 170.0)?;
        range("camera.near", c.near, 1e-4, 1e4)?;
        for (key, v) in [("camera.eye", c.eye), ("camera.target", c.target)] {
            if let Some(v) = v
                && let Some(x) = v.iter().find(|x| !x.is_finite())
            {
                return Err((key, format!("holds {x}, which is not finite")));
            }
        }
        let s = &self.sun;
        range("sun.elevation", s.elevation, 0.0, 90.0)?;
        finite("sun.azimuth", s.azimuth)?;
        rgb("sun.irradiance", s.irradiance)?;
        rgb("sky.zenith_radiance", self.sky.zenith_radiance)?;
        let p = &self.spectrum;
        range("spectrum.wind_speed", p.wind_speed, 1e-3, 100.0)?;
        finite("spectrum.wind_direction", p.wind_direction)?;
        if !(1..=1024).contains(&p.waves) {
            return Err((
                "spectrum.waves",
                format!("= {} is outside 1 to 1024", p.waves),
            ));
        }
        range("spectrum.min_wavelength", p.min_wavelength, 1e-3, 1e4)?;
        range(
            "spectrum.max_wavelength",
            p.max_wavelength,
            p.min_wavelength * (1.0 + 1e-9),
            1e4,
        )?;
        range("spectrum.max_steepness", p.max_steepness, 1e-6, 1.0)?;
        Ok(())
    }

    /// The camera at scene time `time` for a `width × height` image, with `preset` in place of
    /// the file's when given: perspective, infinite far plane, WebGPU's depth range.
    ///
    /// # Errors
    ///
    /// The camera's own checks (an eye on its target, a view straight up or down).
    pub fn camera(
        &self,
        preset: Option<Preset>,
        time: f64,
        width: u32,
        height: u32,
    ) -> Result<Camera, SceneError> {
        let c = &self.camera;
        let (eye, target) = match preset.unwrap_or(c.preset) {
            Preset::Shore => {
                let pitch = 8f64.to_radians();
                let eye = DVec3::new(0.0, 6.0, 0.0);
                (eye, eye + DVec3::new(0.0, -pitch.sin(), -pitch.cos()))
            }
            Preset::Horizon => {
                let eye = DVec3::new(0.0, 4.0, 0.0);
                (eye, eye + DVec3::NEG_Z)
            }
            Preset::High => {
                let pitch = 30f64.to_radians();
                let eye = DVec3::new(0.0, 120.0, 0.0);
                (eye, eye + DVec3::new(0.0, -pitch.sin(), -pitch.cos()))
            }
            Preset::Orbit => {
                let a = core::f64::consts::TAU * (time / ORBIT_PERIOD).fract();
                let eye = FOCUS + DVec3::new(30.0 * a.sin(), 10.0, 30.0 * a.cos());
                (eye, FOCUS)
            }
        };
        let eye = c.eye.map_or(eye, DVec3::from_array);
        let target = c.target.map_or(target, DVec3::from_array);
        if eye.y <= 0.0 {
            return Err(format!(
                "the camera's eye must be above the sea (y > 0), not at y = {}",
                eye.y
            )
            .into());
        }
        Camera::look_at(
            eye,
            target,
            DVec3::Y,
            Projection::Perspective {
                fov_y: c.fov_y.to_radians(),
                aspect: f64::from(width) / f64::from(height),
                near: c.near,
                far: Far::Infinite,
            },
            DepthConvention::ZERO_TO_ONE,
        )
        .map_err(|e| SceneError::Description(format!("camera: {e}")))
    }

    /// The spectrum's parameters.
    pub fn spectrum(&self) -> SpectrumParams {
        let p = &self.spectrum;
        let a = p.wind_direction.to_radians();
        SpectrumParams {
            wind_speed: p.wind_speed,
            wind_direction: DVec2::new(a.cos(), a.sin()),
            waves: p.waves,
            min_wavelength: p.min_wavelength,
            max_wavelength: p.max_wavelength,
            max_steepness: p.max_steepness,
            seed: p.seed,
        }
    }

    /// Sun, sky and sea lighting.
    ///
    /// # Errors
    ///
    /// The lighting model's checks.
    pub fn lighting(&self) -> Result<Lighting, SceneError> {
        let (el, az) = (
            self.sun.elevation.to_radians(),
            self.sun.azimuth.to_radians(),
        );
        let sky = SkyParams {
            sun_direction: DVec3::new(az.sin() * el.cos(), el.sin(), -az.cos() * el.cos()),
            sun_irradiance: DVec3::from_array(self.sun.irradiance),
            zenith_radiance: DVec3::from_array(self.sky.zenith_radiance),
            ..SkyParams::default()
        };
        Lighting::new(sky, SeaParams::default())
            .map_err(|e| SceneError::Description(format!("lighting: {e}")))
    }
}

fn finite(key: &'static str, v: f64) -> Result<(), (&'static str, String)> {
    if v.is_finite() {
        Ok(())
    } else {
        Err((key, format!("= {v} is not finite")))
    }
}

fn rgb(key: &'static str, v: [f64; 3]) -> Result<(), (&'static str, String)> {
    match v.iter().find(|x| !(x.is_finite() && **x >= 0.0)) {
        Some(x) => Err((
            key,
            format!("holds {x}: each component must be finite and >= 0"),
        )),
        None => Ok(()),
    }
}

/// The 1-based line of `section.key` in `text`: the line of table number `index` named
/// `section` (`[section]`, or the `index`th `[[section]]`) that assigns the key (`key =` or
/// `key=`), if any.
fn line_of(text: &str, path: &str, index: usize) -> Option<usize> {
    let (section, key) = path.split_once('.')?;
    let mut current = String::new();
    // Tables named `section` seen so far.
    let mut seen = 0usize;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if let Some(name) = t
            .strip_prefix('[')
            .map(|r| r.trim_start_matches('['))
            .and_then(|r| r.split(']').next())
        {
            current = name.trim().to_string();
            if current == section {
                seen += 1;
            }
            continue;
        }
        if current == section
            && seen == index + 1
            && let Some((k, _)) = t.split_once('=')
            && k.trim() == key
        {
            return Some(i + 1);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_built_in_file_is_the_defaults() {
        let scene = SceneDescription::parse(DEFAULT_SCENE, "default.toml").unwrap();
        // The defaults of every key; the first rock lists the defaults of its keys, the
        // others differ in place, size and shape alone.
        let want = SceneDescription {
            island: Some(IslandSection::default()),
            boxes: vec![WaveBox::default()],
            rocks: scene.rocks.clone(),
            pier: Some(PierSection::default()),
            ..SceneDescription::default()
        };
        assert_eq!(scene, want);
        assert_eq!(scene.rocks.len(), 3);
        assert_eq!(scene.rocks[0], Rock::default());
        for r in &scene.rocks[1..] {
            let same = Rock {
                shore: r.shore,
                offset: r.offset,
                elevation: r.elevation,
                size: r.size,
                heading: r.heading,
                seed: r.seed,
                ..Rock::default()
            };
            assert_eq!(*r, same);
        }
        assert_eq!(scene.spectrum(), SpectrumParams::default());
        // Elevation 25°, azimuth 35° from −z towards +x.
        let sun = scene.lighting().unwrap().sky().sun_direction();
        let (el, az) = (25f64.to_radians(), 35f64.to_radians());
        let want = DVec3::new(az.sin() * el.cos(), el.sin(), -az.cos() * el.cos());
        assert!((sun - want).length() < 1e-15, "{sun} vs {want}");
    }

    #[test]
    fn errors_name_the_line_and_the_key() {
        let cases = [
            // Unknown key: toml's message names it and its line.
            ("[sun]\nelevation = 10.0\nheight = 3\n", "line 3", "height"),
            // Wrong type.
            ("[render]\nwidth = \"wide\"\n", "line 2", "width"),
            // Out of range: our check, with the line found in the text.
            (
                "[spectrum]\nseed = 3\nmax_steepness = 1.5\n",
                "line 3",
                "spectrum.max_steepness",
            ),
            ("[sun]\n\nelevation = 95\n", "line 3", "sun.elevation"),
            ("[camera]\npreset = \"sideways\"\n", "line 2", "sideways"),
            ("[render\nwidth = 3\n", "line 1", ""),
            // The second rock's key, not the first's.
            (
                "[[rocks]]\ncentre = [0.0, 0.0, 0.0]\nmap_size = 64\n[[rocks]]\n\
                 centre = [1.0, 0.0, 0.0]\nmap_size = 100\n",
                "line 6",
                "(rock 2)",
            ),
        ];
        for (text, line, key) in cases {
            let e = SceneDescription::parse(text, "s.toml")
                .unwrap_err()
                .to_string();
            assert!(
                e.starts_with("s.toml") && e.contains(line) && e.contains(key),
                "{text:?}: {e}"
            );
        }
    }

    #[test]
    fn presets_and_explicit_cameras() {
        let scene = SceneDescription::default();
        // The camera gives its eye back from the inverted view matrix: equal up to rounding.
        let eye = |p| scene.camera(Some(p), 0.0, 160, 90).unwrap().eye();
        let close = |a: DVec3, b: DVec3| (a - b).length() < 1e-12 * b.length().max(1.0);
        assert!(close(eye(Preset::Shore), DVec3::new(0.0, 6.0, 0.0)));
        assert!(close(eye(Preset::Horizon), DVec3::new(0.0, 4.0, 0.0)));
        assert!(close(eye(Preset::High), DVec3::new(0.0, 120.0, 0.0)));
        // The orbit starts 30 m behind the focus (+z side) and is a quarter round after 15 s.
        let orbit = |t| scene.camera(Some(Preset::Orbit), t, 160, 90).unwrap().eye();
        assert!(close(orbit(0.0), DVec3::new(0.0, 10.0, -10.0)));
        assert!(close(orbit(15.0), DVec3::new(30.0, 10.0, -40.0)));
        let mut below = scene.clone();
        below.camera.eye = Some([0.0, -1.0, 0.0]);
        assert!(
            below
                .camera(None, 0.0, 16, 9)
                .unwrap_err()
                .to_string()
                .contains("above the sea")
        );
    }
}
