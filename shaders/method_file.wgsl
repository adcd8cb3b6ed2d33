// A method loaded from a file (docs/design.md §5.13): the interface its functions see, and
// how the light loop calls them. Composed after plane.wgsl; the file's own text comes after
// this one, each of its functions by the shape it shades:
//   fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance
//   fn method_sphere(pixel: MethodPixel, light: MethodSphere) -> MethodRadiance
//   fn method_rect(pixel: MethodPixel, light: MethodRect) -> MethodRadiance
//   fn method_disk(pixel: MethodPixel, light: MethodDisk) -> MethodRadiance
//   fn method_tube(pixel: MethodPixel, light: MethodTube) -> MethodRadiance
// A shape without its function is shaded by the lab's method for it (points by `ltc`). The
// Rust side is src/gpu/method_file/mod.rs.

// The shading point as a method sees it, in world space (the plane's normal n is +z).
struct MethodPixel {
    position: vec3<f32>,
    n: vec3<f32>,
    v: vec3<f32>,            // unit, toward the camera
    t1: vec3<f32>,           // the shading frame: t1 along v's tangential part (the
    t2: vec3<f32>,           // tangent for an anisotropic material), t2 = n × t1
    alpha: f32,              // GGX α (roughness squared); α along t1 when anisotropic
    alpha_y: f32,            // α along t2 (alpha while isotropic)
    f0: f32,                 // Fresnel reflectance at normal incidence
    base_color: vec3<f32>,   // the diffuse albedo
    // The side's table at (α, n·v): each lobe's M⁻¹ (maps a direction in the frame
    // (t1, t2, n) to the cosine's), and its magnitude (∫ f cos; the specular one weighted by
    // F0 as Schlick's approximation has it), as the lab's `ltc` reads them.
    spec_minv: mat3x3<f32>,
    spec_magnitude: f32,
    diff_minv: mat3x3<f32>,
    diff_magnitude: f32,
}

// Each light's colour × intensity comes windowed by the lab's range at the light's centre
// (1 for lights without a range). A light with a size emits intensity / area as radiance.
struct MethodPoint {
    position: vec3<f32>,
    intensity: vec3<f32>,
}

struct MethodSphere {
    position: vec3<f32>,
    radius: f32,
    intensity: vec3<f32>,    // radiance intensity / (π r²)
}

struct MethodRect {
    centre: vec3<f32>,
    half_u: vec3<f32>,       // half-edges: corners centre ± half_u ± half_v; it emits
    half_v: vec3<f32>,       // toward half_u × half_v
    intensity: vec3<f32>,    // radiance intensity / (4 |half_u| |half_v|)
}

struct MethodDisk {
    centre: vec3<f32>,
    normal: vec3<f32>,       // unit, the side it emits toward
    radius: f32,
    intensity: vec3<f32>,    // radiance intensity / (π r²)
}

// A capsule: the segment centre ± half_axis swept by a ball of radius r.
struct MethodTube {
    centre: vec3<f32>,
    half_axis: vec3<f32>,
    radius: f32,
    intensity: vec3<f32>,    // radiance 4 intensity / A, A = 4π r² + 4π r |half_axis|
}

// One light's radiance toward the camera: specular, and diffuse with the base colour in it.
struct MethodRadiance {
    specular: vec3<f32>,
    diffuse: vec3<f32>,
}

// The steps a file's loops may take for one light, all loops together, before they are
// stopped (every loop body of the file begins with method_file_over()): a 128-node quadrature
// nested in a 128-node one, and a loop that never ends ends. Below llvmpipe's own cap of
// 65535 iterations a loop, so that this guard, not the driver, stops a loop on every device.
// Initialized here: without an initializer a driver may take it as undefined.
const METHOD_FILE_STEPS: u32 = 16384u;
var<private> method_file_steps: u32 = 0u;

// A step of a file's loop: true once the light's steps are spent (and at every step after,
// so that every loop of the file ends).
fn method_file_over() -> bool {
    method_file_steps = min(method_file_steps, METHOD_FILE_STEPS) + 1u;
    return method_file_steps > METHOD_FILE_STEPS;
}

// The pixel of the side shading with table `ltc`, as MethodPixel.
fn method_pixel(p: Pixel, ltc: LtcShading) -> MethodPixel {
    let w = ltc.magnitudes;
    return MethodPixel(
        p.x,
        vec3<f32>(0.0, 0.0, 1.0),
        p.v,
        p.t1,
        p.t2,
        params.alpha,
        params.alpha_y,
        params.f0,
        params.base_color.rgb,
        ltc.pair.spec.cos_from_brdf,
        w.x,
        ltc.pair.diff.cos_from_brdf,
        w.y,
    );
}

// A light's colour × intensity, windowed at its centre's distance from the pixel.
fn method_intensity(p: Pixel, light: GpuLight) -> vec3<f32> {
    let u = light.position_range.xyz - p.x;
    return light.intensity.rgb * window_falloff_d2(dot(u, u), light.position_range.w);
}

// A file's radiance into the side's sums (whose diffuse already holds the base colour), its
// step count begun again for the next light. A light whose loops were stopped marks the
// render: `partials` after the floor, which resolve turns into the image's alpha.
fn add_method_radiance(s: ptr<function, Sums>, r: MethodRadiance) {
    (*s).spec += r.specular;
    (*s).diff += r.diffuse;
    if method_file_steps > METHOD_FILE_STEPS {
        let k = params.tiles_x * params.tiles_y;
        partials[k] = vec4<f32>(partials[k].x, 1.0, 0.0, 0.0);
    }
    method_file_steps = 0u;
}

// A light by the file's function for its shape. Called only where the file has one.
fn add_method_light(shape: u32, s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    let px = method_pixel(p, ltc);
    let intensity = method_intensity(p, light);
    let centre = light.position_range.xyz;
    // An emitter's dimensions are its second element's (src/gpu/light/mod.rs second_element):
    // `d` a rect's half-edges, a disk's unit normal and radius, a tube's half axis and radius.
    switch shape {
        case SHAPE_SPHERE: {
            add_method_radiance(s, method_sphere(px, MethodSphere(centre, light.intensity.w, intensity)));
        }
        case SHAPE_RECT: {
            let d = extra_element(light);
            add_method_radiance(s, method_rect(px, MethodRect(centre, d.position_range.xyz, d.intensity.xyz, intensity)));
        }
        case SHAPE_DISK: {
            let d = extra_element(light).position_range;
            add_method_radiance(s, method_disk(px, MethodDisk(centre, d.xyz, d.w, intensity)));
        }
        case SHAPE_TUBE: {
            let d = extra_element(light).position_range;
            add_method_radiance(s, method_tube(px, MethodTube(centre, d.xyz, d.w, intensity)));
        }
        default: {
            add_method_radiance(s, method_point(px, MethodPoint(centre, intensity)));
        }
    }
}

// Whether the file shades `shape` (its METHOD_FILE_* constants, written when it is composed).
fn method_file_shades(shape: u32) -> bool {
    switch shape {
        case SHAPE_POINT: { return METHOD_FILE_POINT; }
        case SHAPE_SPHERE: { return METHOD_FILE_SPHERE; }
        case SHAPE_RECT: { return METHOD_FILE_RECT; }
        case SHAPE_DISK: { return METHOD_FILE_DISK; }
        case SHAPE_TUBE: { return METHOD_FILE_TUBE; }
        default: { return false; }
    }
}

// A point light the file does not shade, by the lab's `ltc`, its diffuse times the base colour
// as the file's sums hold it.
fn add_method_fallback_point(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    var t = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    add_ltc(&t, p, ltc, light);
    (*s).spec += t.spec;
    (*s).diff += params.base_color.rgb * t.diff;
}

// Whether some pixel's file stopped a light's loops since the render began.
fn method_file_was_stopped() -> bool {
    return partials[params.tiles_x * params.tiles_y].y > 0.5;
}

// The pixel inspector's values of the file (src/gpu/renderer.rs probe_file): at the image point
// (params.probe_x, probe_y), each light by the side that shades with the file, alone, its
// radiance in accum_0[k] (w 1 where the point is on the plane and seen from above).
@compute @workgroup_size(64)
fn probe_file(@builtin(global_invocation_id) gid: vec3<u32>) {
    let k = gid.x;
    if k >= params.light_count || k >= arrayLength(&accum_0) {
        return;
    }
    let p = prepare(surface_point_at(vec2<f32>(params.probe_x, params.probe_y)));
    var s = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    let seen = p.on_plane && p.v.z > 0.0;
    if seen {
        if METHOD_A == METHOD_FILE {
            add_light(METHOD_FILE, SIDE_A, &s, p, p.ltc_a, lights[k]);
        } else {
            add_light(METHOD_FILE, SIDE_B, &s, p, p.ltc_b, lights[k]);
        }
    }
    accum_0[k] = vec4<f32>(s.spec + s.diff, select(0.0, 1.0, seen));
}
