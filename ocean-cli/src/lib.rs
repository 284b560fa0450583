//! The library behind the `ocean` command (`src/main.rs`): its subcommands, scene files and
//! height-map reader, as modules, so that tests and the fuzz targets (`fuzz/`) can call them
//! without going through the command line.
#![forbid(unsafe_code)]

pub mod bench;
pub mod cone_map;
pub mod interrupt;
pub mod png;
pub mod render;
pub mod shaders;
