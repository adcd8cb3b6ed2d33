// What every emitter's methods share (docs/design.md §5.12), mirroring src/light/mod.rs
// EmitterShading and src/render/shape_methods.rs ShapeMethod::emitter_lobes by name: what the
// methods read beside the shape, and any emitter's unit-radiance lobes by its shape's method.
// Composed with the shapes' files, whose <shape>_emitter_lobes it calls and whose SHAPE_*,
// method overrides and flags (RECTS, DISKS, TUBES) it reads; the Rust side is
// src/gpu/light/emitter.rs.

// What an emitter's methods read beside its shape, in the shading frame: the view, the
// material and the rules (the pixel's LTC lobes come beside it, as `pair`).
struct EmitterShading {
    v: vec3<f32>,
    alpha: vec2<f32>,
    f0: f32,
    clip: u32,
    normalization: u32,
}

// EmitterShading::point_light: an emitter as its oriented point light toward unit `l` with
// `irradiance` at the point — the exact point light where `exact`, the paper's point formula
// else; the form every emitter takes when it is tiny.
fn emitter_shading_point_light(
    pixel: EmitterShading,
    pair: LtcPair,
    l: vec3<f32>,
    irradiance: f32,
    exact: bool,
) -> vec2<f32> {
    let lobes = point_lobes(
        pixel.v,
        l,
        pixel.alpha,
        pixel.f0,
        pair,
        pixel.clip,
        pixel.normalization,
        exact,
    );
    return irradiance * lobes;
}

// emitter_lobes: an emitter's unit-radiance lobes (xy) by side A's (`a`) or B's method for its
// `shape` (the shape's override constants), and the area (z) its radiance I/A divides by.
// `dims` is its light's second element (its dimensions, src/gpu/light/mod.rs second_element)
// and `centre` its centre from the shading point, both mapped to the shading frame by
// `to_frame`. One arm per shape, each under its flag, so that a pipeline without the shape
// holds none of its code; each picks its method inside its arm, so that a side's method is a
// constant there and the shape's shader holds that method alone.
fn emitter_lobes(
    shape: u32,
    a: bool,
    dims: mat2x4<f32>,
    centre: vec3<f32>,
    to_frame: mat3x3<f32>,
    pixel: EmitterShading,
    pair: LtcPair,
) -> vec3<f32> {
    switch shape {
        case SHAPE_RECT: {
            if RECTS {
                let m = select(RECT_B, RECT_A, a);
                return rect_emitter_lobes(m, dims, centre, to_frame, pixel, pair);
            }
        }
        case SHAPE_DISK: {
            if DISKS {
                let m = select(DISK_B, DISK_A, a);
                return disk_emitter_lobes(m, dims, centre, to_frame, pixel, pair);
            }
        }
        case SHAPE_TUBE: {
            if TUBES {
                let m = select(TUBE_B, TUBE_A, a);
                return tube_emitter_lobes(m, dims, centre, to_frame, pixel, pair);
            }
        }
        default: {}
    }
    return vec3<f32>(0.0, 0.0, 1.0);
}
