//! The Ross BRDF (§4).
