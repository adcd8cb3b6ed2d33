// The plane's image for the window: radiance tone-mapped exactly as every PNG is
// (src/output.rs tone_map, same names), the relative difference in false colour, pixels off
// the plane the background; the PNG's sRGB-encoded 8-bit values, which the window draws as
// they are (egui's textures hold gamma-space colours); no read-back is needed to show it.
// Composed alone; its Rust side is src/gpu/display.rs.

// Must match src/gpu/display.rs Display.
struct Display {
    exposure: f32,
    // 0: radiance, 1: relative difference (src/render/mod.rs FrameKind).
    kind: u32,
    _pad0: u32,
    _pad1: u32,
}

@group(0) @binding(0) var<uniform> display: Display;
@group(0) @binding(1) var image: texture_2d<f32>;
@group(0) @binding(2) var shown: texture_storage_2d<rgba8unorm, write>;

// src/output.rs BACKGROUND.
const BACKGROUND: vec3<f32> = vec3<f32>(24.0, 24.0, 28.0) / 255.0;

// The sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
fn srgb_encode(x: f32) -> f32 {
    if x <= 0.0031308 {
        return 12.92 * x;
    }
    return 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

// Radiance × exposure, Reinhard's x / (1 + x) per channel, sRGB; negative shows black.
fn tone_map(radiance: vec3<f32>, exposure: f32) -> vec3<f32> {
    let x = max(radiance * exposure, vec3<f32>(0.0));
    let y = x / (1.0 + x);
    return vec3<f32>(srgb_encode(y.x), srgb_encode(y.y), srgb_encode(y.z));
}

// Position of a relative difference on the colour scale: log10 from 0.1% to 100%.
fn diff_scale_position(rel: f32) -> f32 {
    return clamp((log(max(rel, 1e-30)) / log(10.0) + 3.0) / 3.0, 0.0, 1.0);
}

// src/colormap.rs viridis: R's viridisLite::viridis(9), linear between stops in sRGB.
fn viridis(t: f32) -> vec3<f32> {
    let stops = array<vec3<f32>, 9>(
        vec3<f32>(68.0, 1.0, 84.0),
        vec3<f32>(71.0, 45.0, 123.0),
        vec3<f32>(59.0, 82.0, 139.0),
        vec3<f32>(44.0, 114.0, 142.0),
        vec3<f32>(33.0, 144.0, 140.0),
        vec3<f32>(39.0, 173.0, 129.0),
        vec3<f32>(93.0, 200.0, 99.0),
        vec3<f32>(170.0, 220.0, 50.0),
        vec3<f32>(253.0, 231.0, 37.0),
    );
    let x = clamp(t, 0.0, 1.0) * 8.0;
    let k = min(u32(floor(x)), 7u);
    return mix(stops[k], stops[k + 1u], x - f32(k)) / 255.0;
}

@compute @workgroup_size(16, 16, 1)
fn show(@builtin(global_invocation_id) gid: vec3<u32>) {
    let size = textureDimensions(image);
    if gid.x >= size.x || gid.y >= size.y {
        return;
    }
    let t = textureLoad(image, gid.xy, 0);
    var c = BACKGROUND;
    if t.a >= 0.5 {
        if display.kind == 1u {
            c = viridis(diff_scale_position(t.x));
        } else {
            c = tone_map(t.rgb, display.exposure);
        }
    }
    textureStore(shown, gid.xy, vec4<f32>(c, 1.0));
}
