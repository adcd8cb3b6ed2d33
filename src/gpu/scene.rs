//! `shaders/scene.wgsl`: the uniforms of a render, the light buffer's element and the camera's
//! rays, shared by the plane and binning shaders; here their Pod types (with the WGSL
//! structs' explicit padding) and the uniforms of a render.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use crate::gpu::light::second_element;
use crate::gpu::ltc::{clip_bits, normalization_constant};
use crate::light::Shape;
use crate::render::RenderSettings;
use crate::scene::{Light, Scene};

/// The shader text (composed before plane.wgsl and bin.wgsl).
pub const SOURCE: &str = include_str!("../../shaders/scene.wgsl");

/// The side of a tile in pixels (`TILE_SIDE`): the plane shader's 16×16 workgroup, the unit
/// of binning.
pub const TILE_SIDE: usize = 16;

/// The uniform block; must match `Params` in scene.wgsl (tests/shaders/main.rs checks it against
/// naga's layout of the WGSL struct).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Params {
    pub eye: [f32; 4],
    pub forward: [f32; 4],
    pub right: [f32; 4],
    pub up: [f32; 4],
    pub base_color: [f32; 4],
    pub alpha: f32,
    pub f0: f32,
    pub tan_half_fov: f32,
    pub aspect: f32,
    pub half_size: f32,
    pub divider: f32,
    /// The pixel inspector's point, in pixels of this image (`probe_file` of method_file.wgsl;
    /// unread elsewhere).
    pub probe_x: f32,
    pub probe_y: f32,
    pub width: u32,
    pub height: u32,
    pub light_count: u32,
    pub lut_size: u32,
    pub clip: u32,
    pub normalization: u32,
    pub tiles_x: u32,
    pub tiles_y: u32,
    pub light_start: u32,
    pub light_end: u32,
    pub cull: u32,
    pub tile_capacity: u32,
    pub lut_size_b: u32,
    pub lut_base_b: u32,
    pub lut_base: u32,
    pub bin_row: u32,
    /// α along the bitangent (`alpha` while isotropic).
    pub alpha_y: f32,
    /// The material's unit tangent in the plane (world x, y).
    pub tangent_x: f32,
    pub tangent_y: f32,
    pub aniso_pad: u32,
    /// Table A's 4D table: `[first vec4, axes, stored, 0]` and its node counts
    /// (`gpu::ltc_aniso::aniso_params`); table B's after them.
    pub aniso_a: [u32; 4],
    pub aniso_dims_a: [u32; 4],
    pub aniso_b: [u32; 4],
    pub aniso_dims_b: [u32; 4],
}

/// One light in the storage buffer; must match `GpuLight` in scene.wgsl. A rect takes a second
/// element after all the lights, for its half-edges (`light_elements`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuLight {
    /// xyz position, w the range (≤ 0: infinite).
    pub position_range: [f32; 4],
    /// rgb colour × intensity, w the shape's size (`light_elements`).
    pub intensity: [f32; 4],
}

/// The light buffer of `lights`: one element per light, in order, then one per light whose
/// shape has a second element (`gpu::light::second_element`: its dimensions and its shape's
/// code), which the light's element names by its w, `−(slot + 1)` (exact in f32 for up to
/// 2²⁴ of them, far above `scene::MAX_LIGHTS`).
pub fn light_elements(lights: &[Light]) -> Vec<GpuLight> {
    let mut head = Vec::with_capacity(lights.len());
    let mut tail = Vec::new();
    for l in lights {
        let p = l.position.map(|x| x as f32);
        let i = l.radiant_intensity().as_vec3();
        // A range below f32's smallest normal would round to 0, which encodes "infinite":
        // kept positive, it lights nothing, as on the CPU.
        let range = l.range.map_or(0.0, |r| (r as f32).max(f32::MIN_POSITIVE));
        // The shape: a sphere's radius, 0 for a point, or the slot of its second element
        // below 0 (`gpu::light::second_element`), which scene.wgsl's `light_shape` reads.
        let size = match (l.shape, second_element(l.shape)) {
            (Shape::Sphere { radius }, _) => radius as f32,
            (_, None) => 0.0,
            (_, Some([position_range, intensity])) => {
                tail.push(GpuLight {
                    position_range,
                    intensity,
                });
                -(tail.len() as f32)
            }
        };
        head.push(GpuLight {
            position_range: [p[0], p[1], p[2], range],
            intensity: [i.x, i.y, i.z, size],
        });
    }
    head.extend(tail);
    head
}

/// The elements `light_elements` makes of `lights`: a light with a second element takes two.
pub fn element_count(lights: &[Light]) -> usize {
    lights.len()
        + lights
            .iter()
            .filter(|l| second_element(l.shape).is_some())
            .count()
}

/// Tiles across and down an image.
pub fn tiles(width: usize, height: usize) -> (usize, usize) {
    (width.div_ceil(TILE_SIDE), height.div_ceil(TILE_SIDE))
}

/// The uniforms of a render of `scene` as `settings` says; the chunk, the tables and the
/// binning are set by the renderer.
pub fn params(settings: &RenderSettings, scene: &Scene) -> Params {
    let (eye, forward, right, up) = scene.camera_basis();
    let v4 = |v: DVec3| [v.x as f32, v.y as f32, v.z as f32, 0.0];
    let m = &scene.material;
    let (tiles_x, tiles_y) = tiles(settings.width, settings.height);
    Params {
        eye: v4(eye),
        forward: v4(forward),
        right: v4(right),
        up: v4(up),
        base_color: v4(DVec3::from(m.base_color)),
        alpha: m.alpha as f32,
        alpha_y: m.roughness().y as f32,
        tangent_x: m.tangent().x as f32,
        tangent_y: m.tangent().y as f32,
        f0: m.f0 as f32,
        tan_half_fov: (scene.camera.fov_y_degrees.to_radians() * 0.5).tan() as f32,
        aspect: (settings.width as f64 / settings.height as f64) as f32,
        half_size: scene.plane.half_size as f32,
        divider: settings.divider_column() as f32,
        width: settings.width as u32,
        height: settings.height as u32,
        light_count: scene.lights.len() as u32,
        clip: clip_bits(settings.rules.clipping),
        normalization: normalization_constant(settings.rules.normalization).0,
        tiles_x: tiles_x as u32,
        tiles_y: tiles_y as u32,
        cull: u32::from(settings.cull),
        ..Params::default()
    }
}
