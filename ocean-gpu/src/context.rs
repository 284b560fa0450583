//! The device the passes run on: a headless one created here, or the caller's.

use crate::GpuError;

/// How [`GpuContext::headless_with`] picks its adapter.
#[derive(Clone, Debug)]
pub struct ContextOptions {
    /// Backends to search. `None` reads `WGPU_BACKEND` (for example `vulkan`, `gl`, `metal`,
    /// `dx12`, or a comma-separated list) and falls back to every backend compiled in.
    pub backends: Option<wgpu::Backends>,
    /// Only accept a fallback (software) adapter, such as lavapipe or llvmpipe.
    pub force_fallback_adapter: bool,
    /// Power preference; `None` reads `WGPU_POWER_PREF` (`low`, `high`, `none`).
    pub power_preference: Option<wgpu::PowerPreference>,
    /// Substring (case-insensitive) the adapter name must contain; `None` reads
    /// `WGPU_ADAPTER_NAME`, and no filter applies when that is unset.
    pub adapter_name: Option<String>,
}

impl Default for ContextOptions {
    /// Everything from the environment (`WGPU_BACKEND`, `WGPU_POWER_PREF`,
    /// `WGPU_ADAPTER_NAME`), software adapters accepted.
    fn default() -> Self {
        Self {
            backends: None,
            force_fallback_adapter: false,
            power_preference: None,
            adapter_name: None,
        }
    }
}

/// A device and queue to run the ocean passes on.
///
/// Either created headless ([`GpuContext::headless`]: no surface, any adapter including Mesa's
/// software ones) or wrapping the caller's own device ([`GpuContext::from_device`]), so a wgpu
/// program runs the passes on the device it already renders with. `wgpu::Device` and
/// `wgpu::Queue` are reference-counted handles: the context holds clones, the caller keeps its
/// own.
#[derive(Clone, Debug)]
pub struct GpuContext {
    device: wgpu::Device,
    queue: wgpu::Queue,
    adapter_info: Option<wgpu::AdapterInfo>,
}

/// Limits the headless device asks for: WebGPU's downlevel defaults, so the WGSL that runs here
/// runs on every wgpu backend, in browsers, and on GL 4.3-class drivers (at most 4 storage
/// buffers and 4 storage textures per stage, 16 KiB uniform buffers, 128 MiB storage bindings).
pub fn required_limits() -> wgpu::Limits {
    wgpu::Limits::downlevel_defaults()
}

/// Optional features requested when the adapter has them: GPU timestamps around passes
/// ([`crate::GpuTimer`]). Nothing else is required.
pub const OPTIONAL_FEATURES: wgpu::Features = wgpu::Features::TIMESTAMP_QUERY;

fn backend_names(b: wgpu::Backends) -> String {
    let mut names = Vec::new();
    for (flag, name) in [
        (wgpu::Backends::VULKAN, "vulkan"),
        (wgpu::Backends::GL, "gl"),
        (wgpu::Backends::METAL, "metal"),
        (wgpu::Backends::DX12, "dx12"),
        (wgpu::Backends::BROWSER_WEBGPU, "webgpu"),
    ] {
        if b.contains(flag) {
            names.push(name);
        }
    }
    if names.is_empty() {
        "none".to_owned()
    } else {
        names.join(",")
    }
}

impl GpuContext {
    /// A headless device chosen from the environment: `WGPU_BACKEND` selects the backends
    /// (`vulkan`, `gl`, ...), `WGPU_POWER_PREF` and `WGPU_ADAPTER_NAME` narrow the choice.
    /// Software adapters (lavapipe, llvmpipe) are accepted.
    ///
    /// Fails with [`GpuError::NoAdapter`] (whose message says how to install one) when no
    /// adapter is available, and with [`GpuError::UnsuitableAdapter`] when the adapter lacks
    /// compute shaders or the [`required_limits`].
    pub fn headless() -> Result<Self, GpuError> {
        Self::headless_with(&ContextOptions::default())
    }

    /// A headless device chosen by `options` (fields left `None` come from the environment).
    pub fn headless_with(options: &ContextOptions) -> Result<Self, GpuError> {
        pollster::block_on(Self::headless_async(options))
    }

    /// The asynchronous form of [`GpuContext::headless_with`].
    pub async fn headless_async(options: &ContextOptions) -> Result<Self, GpuError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        if let Some(b) = options.backends {
            desc.backends = b;
        }
        let backends = desc.backends;
        let instance = wgpu::Instance::new(desc);
        let adapter = Self::pick_adapter(&instance, backends, options).await?;
        Self::from_adapter(&adapter).await
    }

    async fn pick_adapter(
        instance: &wgpu::Instance,
        backends: wgpu::Backends,
        options: &ContextOptions,
    ) -> Result<wgpu::Adapter, GpuError> {
        let no_adapter = |reason: String| GpuError::NoAdapter {
            backends: backend_names(backends),
            reason,
        };
        let name = options
            .adapter_name
            .clone()
            .or_else(|| std::env::var("WGPU_ADAPTER_NAME").ok())
            .map(|n| n.to_lowercase());
        if let Some(name) = name {
            let adapters = instance.enumerate_adapters(backends).await;
            let listed: Vec<String> = adapters.iter().map(|a| a.get_info().name).collect();
            return adapters
                .into_iter()
                .find(|a| {
                    a.get_info().name.to_lowercase().contains(&name)
                        && (!options.force_fallback_adapter
                            || a.get_info().device_type == wgpu::DeviceType::Cpu)
                })
                .ok_or_else(|| {
                    no_adapter(format!(
                        "no adapter name contains {name:?} (available: {listed:?})"
                    ))
                });
        }
        let power_preference = options
            .power_preference
            .or_else(wgpu::PowerPreference::from_env)
            .unwrap_or_default();
        instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference,
                force_fallback_adapter: options.force_fallback_adapter,
                compatible_surface: None,
                apply_limit_buckets: false,
            })
            .await
            .map_err(|e| no_adapter(e.to_string()))
    }

    /// A device on `adapter` with the [`required_limits`] (but the adapter's largest 2D
    /// texture) and whichever of the [`OPTIONAL_FEATURES`] the adapter supports.
    pub async fn from_adapter(adapter: &wgpu::Adapter) -> Result<Self, GpuError> {
        let info = adapter.get_info();
        let unsuitable = |reason: String| GpuError::UnsuitableAdapter {
            adapter: format!("{} ({:?})", info.name, info.backend),
            reason,
        };
        let downlevel = adapter.get_downlevel_capabilities();
        if !downlevel
            .flags
            .contains(wgpu::DownlevelFlags::COMPUTE_SHADERS)
        {
            return Err(unsuitable(
                "no compute shaders (OpenGL needs 4.3 or ES 3.1)".to_owned(),
            ));
        }
        let limits = required_limits();
        let mut failed = Vec::new();
        limits.check_limits_with_fail_fn(&adapter.limits(), false, |name, want, have| {
            failed.push(format!("{name}: need {want}, have {have}"));
        });
        if !failed.is_empty() {
            return Err(unsuitable(format!(
                "below the downlevel limits: {}",
                failed.join("; ")
            )));
        }
        let features = adapter.features() & OPTIONAL_FEATURES;
        // Texture sizes are the one limit taken from the adapter: they bound the images a pass
        // can take (a 1080p depth buffer with a guard band exceeds the downlevel 2048), not
        // what the WGSL may use.
        let limits = wgpu::Limits {
            max_texture_dimension_2d: adapter
                .limits()
                .max_texture_dimension_2d
                .max(limits.max_texture_dimension_2d),
            ..limits
        };
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("ocean-gpu headless device"),
                required_features: features,
                required_limits: limits,
                experimental_features: wgpu::ExperimentalFeatures::disabled(),
                memory_hints: wgpu::MemoryHints::Performance,
                trace: wgpu::Trace::Off,
            })
            .await?;
        Ok(Self {
            device,
            queue,
            adapter_info: Some(info),
        })
    }

    /// Wraps the caller's device and queue, so the passes run where the caller renders.
    ///
    /// The passes need compute shaders and at most 4 storage buffers per stage; GPU timing
    /// works when the device was created with [`wgpu::Features::TIMESTAMP_QUERY`].
    pub fn from_device(device: wgpu::Device, queue: wgpu::Queue) -> Self {
        Self {
            device,
            queue,
            adapter_info: None,
        }
    }

    /// [`GpuContext::from_device`] with the adapter's description, for reports.
    pub fn from_device_with_info(
        device: wgpu::Device,
        queue: wgpu::Queue,
        info: wgpu::AdapterInfo,
    ) -> Self {
        Self {
            device,
            queue,
            adapter_info: Some(info),
        }
    }

    /// The device.
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The queue.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// The adapter's description, when known (always for headless contexts).
    pub fn adapter_info(&self) -> Option<&wgpu::AdapterInfo> {
        self.adapter_info.as_ref()
    }

    /// A one-line description: adapter name, backend and driver, or "caller's device".
    pub fn describe(&self) -> String {
        match &self.adapter_info {
            Some(i) => format!(
                "{} ({:?}, {:?}, driver {} {})",
                i.name, i.backend, i.device_type, i.driver, i.driver_info
            ),
            None => "caller's device".to_owned(),
        }
    }

    /// Whether GPU timestamps around passes are available on this device.
    pub fn supports_timestamps(&self) -> bool {
        self.device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY)
    }

    /// Whether multisampled [`crate::LightTargets`] work here: textures of
    /// [`crate::MSAA_SAMPLES`] samples rendered to and then read by shaders. wgpu's GL
    /// backend attaches such textures through the multisampled render-to-texture extension
    /// meant for single-sampled ones, and the draws into them are lost (seen on Mesa's
    /// llvmpipe): false there. True for a caller's device, whose backend is not known.
    pub fn supports_multisampled_light(&self) -> bool {
        self.adapter_info
            .as_ref()
            .is_none_or(|i| i.backend != wgpu::Backend::Gl)
    }

    /// Waits until the GPU has finished all submitted work.
    pub fn wait_idle(&self) -> Result<(), GpuError> {
        self.device.poll(wgpu::PollType::wait_indefinitely())?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backend_names_spell_wgpu_backend_values() {
        // The NoAdapter message prints the searched backends in WGPU_BACKEND's own spelling, so
        // a user can copy them back into the variable.
        assert_eq!(
            backend_names(wgpu::Backends::VULKAN | wgpu::Backends::GL),
            "vulkan,gl"
        );
        assert_eq!(backend_names(wgpu::Backends::empty()), "none");
        for name in ["vulkan", "gl", "metal", "dx12"] {
            assert_eq!(backend_names(wgpu::Backends::from_comma_list(name)), name);
        }
    }

    #[test]
    fn requested_limits_stay_within_webgpu_defaults() {
        // Staying inside WebGPU's defaults keeps the WGSL portable to browsers (ARCHITECTURE.md, "Shaders").
        let l = required_limits();
        assert!(l.check_limits(&wgpu::Limits::defaults()));
        assert_eq!(l.max_storage_buffers_per_shader_stage, 4);
        assert_eq!(l.max_storage_textures_per_shader_stage, 4);
    }

    #[test]
    fn no_adapter_message_tells_how_to_get_one() {
        let e = GpuError::NoAdapter {
            backends: "vulkan".into(),
            reason: "none found".into(),
        };
        let m = e.to_string();
        assert!(m.contains("mesa-vulkan-drivers"), "{m}");
        assert!(m.contains("WGPU_BACKEND=gl"), "{m}");
    }
}
