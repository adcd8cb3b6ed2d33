// One light added to a side's sums by the side's method for its shape (docs/design.md §5.12):
// the shapes' method codes, the pipeline constants that pick them, and add_light with one arm
// per shape. Composed after scene.wgsl and before plane.wgsl, whose Sums, Pixel, LtcShading,
// is_factored and add_point it uses; the Rust side is src/gpu/light/light_shape.rs.

// How a side shades a sphere (src/light/sphere/mod.rs SphereMethod; light_shape.rs
// sphere_constant).
const SPHERE_EXACT: u32 = 0u;                // the BRDF over the cap (sphere_light.wgsl)
const SPHERE_LTC_POINT: u32 = 1u;            // the paper's point formula at the centre
const SPHERE_LTC_DISK: u32 = 2u;             // Heitz & Hill 2017's LTC disk
const SPHERE_REPRESENTATIVE_POINT: u32 = 3u; // Karis 2013

// How a side shades a rect (src/light/rect/mod.rs RectMethod; light_shape.rs rect_constant).
const RECT_EXACT: u32 = 0u;          // the BRDF over the rect above the surface (rect_light.wgsl)
const RECT_LTC_POLYGON: u32 = 1u;    // Heitz et al. 2016: clipped, M⁻¹, Lambert's edge formula
const RECT_LTC_PROXY: u32 = 2u;      // Heitz & Hill 2017: the sphere of the same form factor
const RECT_LTC_PROXY_FAST: u32 = 3u; // three.js's closed form of the proxy
const RECT_LTC_POINT: u32 = 4u;      // the centre as an oriented point light

// How a side shades a disk (src/light/disk/mod.rs DiskMethod; light_shape.rs disk_constant).
const DISK_EXACT: u32 = 0u;     // the BRDF over the disk above the surface (disk_light.wgsl)
const DISK_LTC_DISK: u32 = 1u;  // Heitz & Hill 2017: the disk's cone mapped by M⁻¹
const DISK_LTC_POINT: u32 = 2u; // the centre as an oriented point light

// The shapes whose dimensions take a second element of the light buffer, which holds the code
// in its last w (src/gpu/light/mod.rs shape_constant and second_element; scene.wgsl's
// light_shape reads it back).
const SHAPE_RECT: u32 = 2u;
const SHAPE_DISK: u32 = 3u;
const SHAPE_TUBE: u32 = 4u;

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

// Some light is not a point: without one, the light loop has no test of the shape at all.
override SIZED: bool = false;
// How A and B shade the lights with a size: constants too, so that a pipeline holds only the
// sphere methods it uses (the exact one's loops would weigh on every other's registers).
override SPHERE_A: u32 = SPHERE_LTC_DISK;
override SPHERE_B: u32 = SPHERE_EXACT;
// Some light is a rect, and how A and B shade rects (constants for the same reason).
override RECTS: bool = false;
override RECT_A: u32 = RECT_LTC_POLYGON;
override RECT_B: u32 = RECT_EXACT;
// Some light is a disk, and how A and B shade disks.
override DISKS: bool = false;
override DISK_A: u32 = DISK_LTC_DISK;
override DISK_B: u32 = DISK_EXACT;

// A light's lobes (specular, diffuse; at unit intensity) times its colour × intensity into the
// side's sums; into factored sums divided by the pixel's factors, as add_brdf_factored does.
fn add_lobes(method: u32, s: ptr<function, Sums>, ltc: LtcShading, light: GpuLight, lobes: vec2<f32>) {
    var l = lobes;
    if is_factored(method) {
        l /= vec2<f32>(ltc.spec_factor, ltc.diff_factor);
    }
    (*s).spec += light.intensity.rgb * l.x;
    if method == METHOD_FILE {
        // A file's diffuse sum holds the base colour (method_file.wgsl).
        (*s).diff += params.base_color.rgb * light.intensity.rgb * l.y;
    } else {
        (*s).diff += light.intensity.rgb * l.y;
    }
}

// A light with a size by the side's sphere method (src/cpu/mod.rs sphere_term), in the shading
// frame; into factored sums divided by the factors, as add_brdf_factored does.
fn add_sphere(
    method: u32,
    sphere: u32,
    s: ptr<function, Sums>,
    p: Pixel,
    ltc: LtcShading,
    light: GpuLight,
) {
    let shading = SphereShading(
        p.v_tangent,
        p.tangent_from_world * (light.position_range.xyz - p.x),
        1.0,
        light.position_range.w,
        light.intensity.w,
        material_alpha(),
        params.f0,
        params.clip,
        params.normalization,
    );
    let cap = cap_of_sphere(shading.u, shading.radius);
    var lobes: vec2<f32>;
    if cap.sin_sigma < POINT_LIMIT_SIN_SIGMA {
        let exact = sphere == SPHERE_EXACT || sphere == SPHERE_REPRESENTATIVE_POINT;
        lobes = sphere_point(shading, ltc.pair, exact);
    } else {
        switch sphere {
            case SPHERE_EXACT: { lobes = sphere_rule(shading, cap); }
            case SPHERE_LTC_DISK: { lobes = sphere_ltc_disk(shading, ltc.pair, cap); }
            case SPHERE_REPRESENTATIVE_POINT: { lobes = sphere_representative_point(shading, cap); }
            default: { lobes = sphere_ltc_point(shading, ltc.pair); }
        }
    }
    add_lobes(method, s, ltc, light, lobes);
}

// An emitter's unit-radiance lobes into the side's sums: times its radiance I/A (`area` A)
// and the window at its centre's distance (`centre`, world), as src/cpu/mod.rs
// emitter_radiance scales them; every emitter's one tail.
fn add_emitter_lobes(
    method: u32,
    s: ptr<function, Sums>,
    ltc: LtcShading,
    light: GpuLight,
    centre: vec3<f32>,
    area: f32,
    unit: vec2<f32>,
) {
    var lobes = unit;
    let scale = window_falloff_d2(dot(centre, centre), light.position_range.w) / area;
    lobes *= scale;
    add_lobes(method, s, ltc, light, lobes);
}

// A rect by the side's rect method (src/cpu/mod.rs emitter_term): its radiance I/A times the
// unit-radiance lobes, windowed at the centre's distance; into factored sums as add_sphere.
fn add_rect(
    method: u32,
    rect: u32,
    s: ptr<function, Sums>,
    p: Pixel,
    ltc: LtcShading,
    light: GpuLight,
) {
    let edges = rect_half_edges(light);
    let centre = light.position_range.xyz - p.x;
    let shading = RectShading(
        p.v_tangent,
        Rect(p.tangent_from_world * centre, p.tangent_from_world * edges[0], p.tangent_from_world * edges[1]),
        material_alpha(),
        params.f0,
        params.clip,
        params.normalization,
    );
    let lobes = rect_light(rect, shading, ltc.pair);
    add_emitter_lobes(method, s, ltc, light, centre, rect_area(shading.rect), lobes);
}

// A disk by the side's disk method (src/cpu/mod.rs emitter_term): its radiance I/(π r²) times the
// unit-radiance lobes, windowed at the centre's distance; into factored sums as add_sphere.
fn add_disk(
    method: u32,
    disk: u32,
    s: ptr<function, Sums>,
    p: Pixel,
    ltc: LtcShading,
    light: GpuLight,
) {
    let normal_radius = disk_normal_radius(light);
    let centre = light.position_range.xyz - p.x;
    let shading = DiskShading(
        p.v_tangent,
        Disk(p.tangent_from_world * centre, p.tangent_from_world * normal_radius.xyz, normal_radius.w),
        material_alpha(),
        params.f0,
        params.clip,
        params.normalization,
    );
    let lobes = disk_light(disk, shading, ltc.pair);
    add_emitter_lobes(method, s, ltc, light, centre, disk_area(shading.disk), lobes);
}

// A tube by the side's tube method (src/cpu/mod.rs emitter_term): its radiance 4I/A times the
// unit-radiance lobes, windowed at the centre's distance; into factored sums as add_sphere.
fn add_tube(
    method: u32,
    tube: u32,
    s: ptr<function, Sums>,
    p: Pixel,
    ltc: LtcShading,
    light: GpuLight,
) {
    let axis_radius = tube_half_axis_radius(light);
    let centre = light.position_range.xyz - p.x;
    let shading = TubeShading(
        p.v_tangent,
        Tube(
            p.tangent_from_world * (centre - axis_radius.xyz),
            p.tangent_from_world * (centre + axis_radius.xyz),
            axis_radius.w,
        ),
        material_alpha(),
        params.f0,
        params.clip,
        params.normalization,
    );
    let lobes = tube_light(tube, shading, ltc.pair);
    add_emitter_lobes(method, s, ltc, light, centre, 0.25 * tube_area(shading.tube), lobes);
}

// The two sides of the split, which add_light is told which of (their constants follow).
const SIDE_A: u32 = 0u;
const SIDE_B: u32 = 1u;

// One light by one side: by the side's method for the light's shape, one arm per shape
// (src/cpu/mod.rs light_term), each shape's method the side's override constant. Where every
// light is a point (SIZED off) the loop has no test of the shape at all; without a rect
// (RECTS off), no rect arm, and so for disks and tubes.
fn add_light(
    method: u32,
    side: u32,
    s: ptr<function, Sums>,
    p: Pixel,
    ltc: LtcShading,
    light: GpuLight,
) {
    var shape = SHAPE_POINT;
    if SIZED {
        shape = light_shape(light);
    }
    // A method file's function for the shape, where it has one (method_file.wgsl).
    if method == METHOD_FILE && method_file_shades(shape) {
        add_method_light(shape, s, p, ltc, light);
        return;
    }
    let a = side == SIDE_A;
    switch shape {
        case SHAPE_SPHERE: { add_sphere(method, select(SPHERE_B, SPHERE_A, a), s, p, ltc, light); }
        case SHAPE_RECT: {
            if RECTS {
                add_rect(method, select(RECT_B, RECT_A, a), s, p, ltc, light);
            }
        }
        case SHAPE_DISK: {
            if DISKS {
                add_disk(method, select(DISK_B, DISK_A, a), s, p, ltc, light);
            }
        }
        case SHAPE_TUBE: {
            if TUBES {
                add_tube(method, select(TUBE_B, TUBE_A, a), s, p, ltc, light);
            }
        }
        default: { add_point(method, s, p, ltc, light); }
    }
}
