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

// A light's shape (src/light/mod.rs Shape; src/gpu/scene.rs shape_constant).
const SHAPE_POINT: u32 = 0u;
const SHAPE_SPHERE: u32 = 1u;
const SHAPE_RECT: u32 = 2u;
const SHAPE_DISK: u32 = 3u;
const SHAPE_TUBE: u32 = 4u;

// The shape light_elements wrote: a sphere's radius in w, 0 for a point, the slot of a rect's,
// a disk's or a tube's second element below 0 (a disk's holds 1 in its last w, a tube's 2).
fn light_shape(light: GpuLight) -> u32 {
    if light.intensity.w > 0.0 {
        return SHAPE_SPHERE;
    }
    if light.intensity.w < 0.0 {
        let kind = extra_element(light).intensity.w;
        if kind > 1.5 {
            return SHAPE_TUBE;
        }
        if kind > 0.0 {
            return SHAPE_DISK;
        }
        return SHAPE_RECT;
    }
    return SHAPE_POINT;
}

// A rect's or a disk's second element, after the lights (light_elements).
fn extra_element(light: GpuLight) -> GpuLight {
    return lights[params.light_count + u32(-light.intensity.w) - 1u];
}

// A rect's half-edges, from its second element.
fn rect_half_edges(light: GpuLight) -> mat2x3<f32> {
    let extra = extra_element(light);
    return mat2x3<f32>(extra.position_range.xyz, extra.intensity.xyz);
}

// A disk's unit normal (xyz) and radius (w), from its second element.
fn disk_normal_radius(light: GpuLight) -> vec4<f32> {
    return extra_element(light).position_range;
}

// A tube's half axis (xyz) and radius (w), from its second element.
fn tube_half_axis_radius(light: GpuLight) -> vec4<f32> {
    return extra_element(light).position_range;
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
