//! Shared parts of the fuzz targets (`fuzz_targets/`): the input reader, the invariants and the
//! C ABI call sequences. See FUZZING.md at the repository root.

pub mod call;
pub mod check;
pub mod cmem;
pub mod finite;
pub mod input;
pub mod known;
pub mod live;
pub mod misuse;
pub mod ops_lighting;
pub mod ops_relief;
pub mod ops_sao;
pub mod ops_scene;
pub mod ops_spectrum;
pub mod ops_waves;
pub mod sequence;
