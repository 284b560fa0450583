//! wgpu backend of the ocean crates.
