// The scene on the GPU: the uniforms of a render, one light, and the camera's rays onto the
// plane z = 0 (src/scene/mod.rs camera_ray, surface_point). Composed first into both the plane
// shader and the binning shader; its Rust side is src/gpu/scene.rs.

// Must match src/gpu/scene.rs Params (checked by tests/shaders/main.rs).
struct Params {
    eye: vec4<f32>,        // xyz camera position
    forward: vec4<f32>,    // xyz unit view direction
    right: vec4<f32>,      // xyz unit
    up: vec4<f32>,         // xyz unit
    base_color: vec4<f32>, // rgb diffuse albedo
    alpha: f32,
    f0: f32,
    tan_half_fov: f32,
    aspect: f32,
    half_size: f32,
    divider: f32,          // first pixel column of B in the split view
    probe_x: f32,          // the pixel inspector's point, in pixels (method_file.wgsl probe_file)
    probe_y: f32,
    width: u32,
    height: u32,
    light_count: u32,
    lut_size: u32,         // table A: cells per side, at the start of the LUT buffer
    clip: u32,
    normalization: u32,
    tiles_x: u32,          // 16×16-pixel tiles (one workgroup each)
    tiles_y: u32,
    light_start: u32,      // the chunk of each pixel's light list this dispatch sums
    light_end: u32,
    cull: u32,             // 1: each tile sums its own list of lights in range
    tile_capacity: u32,    // entries the tile lists hold; beyond it, every tile sums all
    lut_size_b: u32,       // table B (method B's own table), after table A in the buffer
    lut_base_b: u32,       // its first vec4
    lut_base: u32,         // table A's first vec4 (B's, where B is shown alone)
    bin_row: u32,          // the first tile row a band of binning or shading works on
    alpha_y: f32,          // α along the bitangent (alpha while isotropic)
    tangent_x: f32,        // the material's unit tangent in the plane (ltc_aniso.wgsl)
    tangent_y: f32,
    aniso_pad: u32,
    aniso_a: vec4<u32>,    // table A's 4D table: first vec4, axes, stored (AnisoTable)
    aniso_dims_a: vec4<u32>,
    aniso_b: vec4<u32>,    // table B's
    aniso_dims_b: vec4<u32>,
}

// The material's roughness along the shading frame's x and y (equal while isotropic).
fn material_alpha() -> vec2<f32> {
    return vec2<f32>(params.alpha, params.alpha_y);
}

// Must match src/gpu/scene.rs GpuLight: position and range (≤ 0: infinite), colour × intensity
// and the shape's size (light_elements: 0 a point, a sphere's radius, −(slot + 1) for a rect,
// whose half-edges are the xyz of element light_count + slot).
struct GpuLight {
    position_range: vec4<f32>,
    intensity: vec4<f32>,
}

// A light's shape (src/light/mod.rs ShapeKind; src/gpu/light/mod.rs shape_constant): the two
// that one element holds. A shape with a second element has its code in that element's last w,
// which light_shape.wgsl names.
const SHAPE_POINT: u32 = 0u;
const SHAPE_SPHERE: u32 = 1u;

// The shape light_elements wrote: a sphere's radius in w, 0 for a point, or below 0 the slot
// of the light's second element, whose last w holds the shape's code (a small integer, exact
// in f32; rounded, not truncated, so that nothing rests on its last bit).
fn light_shape(light: GpuLight) -> u32 {
    if light.intensity.w > 0.0 {
        return SHAPE_SPHERE;
    }
    if light.intensity.w < 0.0 {
        return u32(extra_element(light).intensity.w + 0.5);
    }
    return SHAPE_POINT;
}

// A light's second element, after the lights (light_elements).
fn extra_element(light: GpuLight) -> GpuLight {
    return lights[params.light_count + u32(-light.intensity.w) - 1u];
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> lights: array<GpuLight>;

// The side of a tile, in pixels: the plane shader's workgroup, the binning's unit.
const TILE_SIDE: u32 = 16u;

// Scene::camera_ray: the unit ray through image position `pos` (pixels, centres at k + ½).
fn camera_ray(pos: vec2<f32>) -> vec3<f32> {
    let size = vec2<f32>(f32(params.width), f32(params.height));
    let s = pos / size * 2.0 - 1.0;
    return normalize(params.forward.xyz
        + s.x * params.tan_half_fov * params.aspect * params.right.xyz
        - s.y * params.tan_half_fov * params.up.xyz);
}

// Where a ray from the eye meets the plane z = 0: the point in xyz, w = 1 if it does in front
// of the eye, 0 if not.
fn plane_hit(dir: vec3<f32>) -> vec4<f32> {
    if dir.z == 0.0 {
        return vec4<f32>(0.0);
    }
    let t = -params.eye.z / dir.z;
    if t <= 0.0 {
        return vec4<f32>(0.0);
    }
    return vec4<f32>(params.eye.xyz + t * dir, 1.0);
}
