//! Every shader's export to every language, snapshotted (`snapshots/`): a changed translation
//! is a reviewed change. Text exports are recorded in full; SPIR-V as its header, word count and
//! hash.

use ocean_gpu::shaders::{Code, Export, Language, all, export};

/// FNV-1a, 64-bit: a stable hash for snapshotting binary output.
fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// A deterministic, human-readable record of an export: bindings table, then each file
/// (text in full; SPIR-V as a header summary, word count and FNV-1a hash).
fn snapshot_text(e: &Export) -> String {
    let mut out = e.bindings_table();
    for f in &e.files {
        out.push_str(&format!("\n===== {} =====\n", f.file_name));
        match &f.code {
            Code::Text(t) => out.push_str(t),
            Code::Binary(b) => {
                let words: Vec<u32> = b
                    .chunks_exact(4)
                    .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                    .collect();
                out.push_str(&format!(
                    "magic {:#010x}\nversion {}.{}\nid bound {}\nwords {}\nfnv1a64 {:#018x}\n",
                    words[0],
                    (words[1] >> 16) & 0xff,
                    (words[1] >> 8) & 0xff,
                    words[3],
                    words.len(),
                    fnv1a(b)
                ));
            }
        }
    }
    out
}

#[test]
fn exports_match_snapshots() {
    for s in all() {
        for l in Language::ALL {
            let e = s.export(l).unwrap_or_else(|err| panic!("{err}"));
            insta::assert_snapshot!(format!("{}_{}", s.name, l.name()), snapshot_text(&e));
        }
    }
}

#[test]
fn spirv_is_a_valid_module_header() {
    let e = export("trochoid", Language::SpirV).unwrap();
    let Code::Binary(b) = &e.files[0].code else {
        panic!("SPIR-V is binary")
    };
    assert_eq!(b.len() % 4, 0);
    // SPIR-V magic number, little-endian, and version 1.0 (0x00010000).
    assert_eq!(&b[..4], &0x0723_0203u32.to_le_bytes());
    assert_eq!(&b[4..8], &0x0001_0000u32.to_le_bytes());
}
