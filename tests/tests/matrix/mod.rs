//! The bad-input matrix's generator: the header parser and the C program it writes (see
//! `tests/tests/c_matrix.rs`).

pub mod classify;
pub mod generate;
pub mod header;
pub mod variants;
