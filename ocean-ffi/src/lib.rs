//! C ABI of the ocean crates.
