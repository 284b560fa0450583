//! The rocks' cone maps cached on disk between runs of `ocean render`: generating a relaxed cone
//! map is the slowest part of the start-up (a quarter of a second at 256², seconds at 1024²),
//! and the same scene makes the same maps.
//!
//! The cache lives in `$OCEAN_CACHE_DIR`, else `$XDG_CACHE_HOME/ocean`, else
//! `$HOME/.cache/ocean`. A file is named after a hash of everything the cones depend on (the
//! height map's texels, its edge mode, the cone parameters and this format's version) and holds
//! the three channels of the map with a checksum. A file that is missing, short, of another
//! version or whose checksum fails is ignored and written again; a cache that cannot be written
//! costs nothing but the next run's time. Cone generation is deterministic, so a cached map is
//! bit for bit the one the run would make.

use std::path::PathBuf;

use ocean_relief::{ConeMap, ConeParams, Edge, HeightMap};

/// Bumped whenever the layout or the generator's output changes (3: cones bounded over parts of
/// cells and their path boxes, wider than version 2's).
const VERSION: u32 = 3;
const MAGIC: &[u8; 4] = b"OCNC";

/// FNV-1a, 64 bits.
fn fnv1a(bytes: impl IntoIterator<Item = u8>, mut h: u64) -> u64 {
    for b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

/// The cache directory, if the environment names one.
pub fn dir() -> Option<PathBuf> {
    let var = |k| {
        std::env::var_os(k)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    var("OCEAN_CACHE_DIR")
        .or_else(|| var("XDG_CACHE_HOME").map(|d| d.join("ocean")))
        .or_else(|| var("HOME").map(|d| d.join(".cache").join("ocean")))
}

/// The key of the cones of `map` for `params`.
fn key(map: &HeightMap, params: &ConeParams) -> u64 {
    let mut h = fnv1a(VERSION.to_le_bytes(), FNV_OFFSET);
    h = fnv1a((map.size() as u64).to_le_bytes(), h);
    h = fnv1a([u8::from(map.edge() == Edge::Wrap)], h);
    h = fnv1a(format!("{params:?}").into_bytes(), h);
    fnv1a(map.depths().iter().flat_map(|d| d.to_le_bytes()), h)
}

fn encode(cones: &ConeMap, key: u64) -> Vec<u8> {
    let mut out = Vec::with_capacity(24 + 12 * cones.ratios().len() + 8);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&(cones.size() as u32).to_le_bytes());
    out.extend_from_slice(&[u8::from(cones.edge() == Edge::Wrap), 0, 0, 0]);
    out.extend_from_slice(&key.to_le_bytes());
    for channel in [cones.ratios(), cones.clearance(), cones.near_cap()] {
        for v in channel {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    let sum = fnv1a(out.iter().copied(), FNV_OFFSET);
    out.extend_from_slice(&sum.to_le_bytes());
    out
}

/// The cones in `bytes` if they are a whole, intact file for `key` and a map of `size`.
fn decode(bytes: &[u8], key: u64, size: usize, edge: Edge) -> Option<ConeMap> {
    let n = size * size;
    let body = 24 + 12 * n;
    if bytes.len() != body + 8 || &bytes[..4] != MAGIC {
        return None;
    }
    let word = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap_or([0; 4]));
    let long = |at: usize| u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap_or([0; 8]));
    let wrap = bytes[12] == 1;
    if word(4) != VERSION
        || word(8) as usize != size
        || wrap != (edge == Edge::Wrap)
        || long(16) != key
        || long(body) != fnv1a(bytes[..body].iter().copied(), FNV_OFFSET)
    {
        return None;
    }
    let channel = |c: usize| -> Vec<f32> {
        bytes[24 + 4 * n * c..24 + 4 * n * (c + 1)]
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect()
    };
    ConeMap::from_channels(size, edge, channel(0), channel(1), channel(2)).ok()
}

/// Whether [`cones`] found the map in the cache or made it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    Cached,
    Generated,
}

/// The cones of `map` for `params`: from the cache when it holds them, else generated (and
/// stored when the cache is writable).
///
/// # Errors
///
/// The generator's errors.
pub fn cones(
    map: &HeightMap,
    params: ConeParams,
) -> Result<(ConeMap, Source), ocean_relief::ReliefError> {
    let k = key(map, &params);
    let path = dir().map(|d| d.join(format!("cones-{}-{k:016x}.bin", map.size())));
    if let Some(p) = &path
        && let Ok(bytes) = std::fs::read(p)
        && let Some(c) = decode(&bytes, k, map.size(), map.edge())
    {
        return Ok((c, Source::Cached));
    }
    let cones = ConeMap::generate(map, params)?;
    if let Some(p) = &path {
        // A cache that cannot be written is no error: the next run generates again.
        if p.parent()
            .is_some_and(|d| std::fs::create_dir_all(d).is_ok())
        {
            let _ = crate::image_file::write_atomically(p, &encode(&cones, k), || Ok(()));
        }
    }
    Ok((cones, Source::Generated))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map() -> HeightMap {
        let n = 32;
        let h = ocean_relief::maps::value_noise(n, 4, 3, 9);
        ocean_relief::maps::to_map(n, &h, Edge::Wrap).unwrap()
    }

    /// A stored map decodes to the same cones; any change of a byte, of the key, the size or
    /// the edge mode, or a truncation, is refused.
    #[test]
    fn round_trip_and_refusals() {
        let m = map();
        let params = ConeParams::relaxed(4.0);
        let cones = ConeMap::generate(&m, params).unwrap();
        let k = key(&m, &params);
        let bytes = encode(&cones, k);
        assert_eq!(decode(&bytes, k, 32, Edge::Wrap), Some(cones.clone()));
        assert_eq!(decode(&bytes, k ^ 1, 32, Edge::Wrap), None);
        assert_eq!(decode(&bytes, k, 16, Edge::Wrap), None);
        assert_eq!(decode(&bytes, k, 32, Edge::Clamp), None);
        assert_eq!(decode(&bytes[..bytes.len() - 1], k, 32, Edge::Wrap), None);
        for at in [0, 5, 30, bytes.len() / 2, bytes.len() - 3] {
            let mut bad = bytes.clone();
            bad[at] ^= 0x10;
            assert_eq!(decode(&bad, k, 32, Edge::Wrap), None, "byte {at}");
        }
        // The key follows the heights and the parameters.
        assert_ne!(key(&m, &ConeParams::relaxed(2.0)), k);
        let other = ocean_relief::maps::to_map(
            32,
            &ocean_relief::maps::value_noise(32, 4, 3, 10),
            Edge::Wrap,
        )
        .unwrap();
        assert_ne!(key(&other, &params), k);
    }
}
