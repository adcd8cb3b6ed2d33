//! `lut --export aniso-texture`'s layout (src/gpu/ltc_aniso/export.rs): its textures decode to
//! the lab's table, node for node and between nodes, and its lookup is valid WGSL that reads
//! the textures where the lab's shader reads its buffer.

use glam::DVec3;
use ltc_lab::brdf::Alpha;
use ltc_lab::gpu::ltc_aniso::export;
use ltc_lab::ltc::aniso::source::AnisoSource;
use ltc_lab::ltc::aniso::{AnisoAxes, AnisoCell, AnisoLut};

/// A table made again from the exported bytes: the three volumes' texels back into cells.
fn decoded(lut: &AnisoLut, bytes: &[u8]) -> AnisoLut {
    let volumes = export::read_texels(bytes, lut.cells.len()).expect("the exported size");
    let cells = (0..lut.cells.len())
        .map(|k| {
            let [r0, r1, r2] = [0, 1, 2].map(|v| volumes[v][k]);
            AnisoCell {
                m: [
                    r0[0], r0[1], r0[2], r0[3], r1[0], r1[1], r1[2], r1[3], r2[0],
                ],
                norm: r2[1],
                fresnel: r2[2],
                // The error channel stays with the lab (the shader never reads it).
                err: lut.cells[k].err,
            }
        })
        .collect();
    AnisoLut {
        cells,
        ..lut.clone()
    }
}

/// Every node's numbers come back to the bit, so any point's lobe does too: the lookup is the
/// same arithmetic on the same numbers. Checked for the lab's table and both of I3D 2022's.
#[test]
fn exported_textures_decode_to_the_tables_values() {
    let sources = [
        AnisoSource::Lab,
        AnisoSource::I3d(AnisoAxes::I3dAlphaXY),
        AnisoSource::I3d(AnisoAxes::I3dAlphaLambda),
    ];
    for source in sources {
        let lut = source.load().unwrap();
        let bytes = export::texture_bytes(&lut);
        let [w, h, d] = export::texture_size(&lut);
        assert_eq!(bytes.len(), export::TEXTURES * w * h * d * 16);
        let back = decoded(&lut, &bytes);
        for (k, (a, b)) in lut.cells.iter().zip(&back.cells).enumerate() {
            assert_eq!(
                (a.m, a.norm, a.fresnel),
                (b.m, b.norm, b.fresnel),
                "{}: node {k}",
                source.name()
            );
        }
        for k in 0..200 {
            let t = k as f64 / 200.0;
            let alpha = Alpha {
                x: 0.02 + 0.9 * t,
                y: 0.01 + 0.5 * (7.0 * t).fract(),
            };
            let (theta, phi) = (1.5 * (3.0 * t).fract(), 6.2 * (11.0 * t).fract());
            let v = DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let (a, b) = (lut.ltc(alpha, v), back.ltc(alpha, v));
            assert_eq!(
                a.cos_from_brdf,
                b.cos_from_brdf,
                "{} at {alpha:?}, {v}",
                source.name()
            );
            assert_eq!((a.norm, a.fresnel), (b.norm, b.fresnel));
        }
    }
}

/// The lookup validates as WGSL on its own, reads the three textures, and is the lab's
/// shader with only the buffer read changed (the replaced text is still there to replace).
#[test]
fn exported_lookup_is_valid_wgsl_reading_the_textures() {
    let lut = AnisoLut::shipped();
    let text = export::wgsl(lut, "a test");
    assert!(
        ltc_lab::gpu::ltc_aniso::SOURCE.contains(export::BUFFER_READ),
        "shaders/ltc_aniso.wgsl's buffer read changed: update the export's replacement"
    );
    assert!(!text.contains("lut["), "a buffer read is left");
    let module = naga::front::wgsl::parse_str(&text).unwrap_or_else(|e| {
        panic!("{}", e.emit_to_string(&text));
    });
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&text)));
    let globals: Vec<&str> = module
        .global_variables
        .iter()
        .filter_map(|(_, g)| g.name.as_deref())
        .collect();
    assert_eq!(globals, ["ltc_aniso_0", "ltc_aniso_1", "ltc_aniso_2"]);
    for f in ["aniso_ltc", "ltc_aniso_table", "aniso_sample"] {
        assert!(
            module
                .functions
                .iter()
                .any(|(_, g)| g.name.as_deref() == Some(f)),
            "{f} missing"
        );
    }
}
