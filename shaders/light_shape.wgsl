// One light added to a side's sums by the side's method for its shape (docs/design.md §5.12):
// add_light, by add_point, add_sphere or, for every emitter, add_emitter (emitter.wgsl's
// emitter_lobes). Composed after scene.wgsl and before plane.wgsl, whose Sums, Pixel,
// LtcShading, is_factored and add_point it uses; the Rust side is src/gpu/light/light_shape.rs.

// The shapes' codes, their methods' codes and the override constants that pick them are
// each shape's own file's (sphere_light.wgsl, rect_light.wgsl, …); scene.wgsl's light_shape
// reads a light's code back from the last w of its second element.

// Some light is not a point: without one, the light loop has no test of the shape at all.
override SIZED: bool = false;

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

// An emitter (a light with a second element: a rect, a disk, a tube) by side A's (`a`) or
// B's method for its shape (src/cpu/mod.rs emitter_term): its radiance I/A times
// emitter_lobes' unit-radiance lobes, windowed at its centre's distance; into factored sums
// as add_sphere.
fn add_emitter(
    method: u32,
    shape: u32,
    a: bool,
    s: ptr<function, Sums>,
    p: Pixel,
    ltc: LtcShading,
    light: GpuLight,
) {
    let extra = extra_element(light);
    let dims = mat2x4<f32>(extra.position_range, extra.intensity);
    let centre = light.position_range.xyz - p.x;
    let pixel = EmitterShading(
        p.v_tangent,
        material_alpha(),
        params.f0,
        params.clip,
        params.normalization,
    );
    let unit = emitter_lobes(shape, a, dims, centre, p.tangent_from_world, pixel, ltc.pair);
    var lobes = unit.xy;
    let scale = window_falloff_d2(dot(centre, centre), light.position_range.w) / unit.z;
    lobes *= scale;
    add_lobes(method, s, ltc, light, lobes);
}

// The two sides of the split, which add_light is told which of (their constants follow).
const SIDE_A: u32 = 0u;
const SIDE_B: u32 = 1u;

// One light by one side: by the side's method for the light's shape (src/cpu/mod.rs
// light_term), each shape's method the side's override constant. Where every light is a point
// (SIZED off) the loop has no test of the shape at all; an emitter's shape no light has, no
// arm in emitter_lobes.
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
        case SHAPE_POINT: { add_point(method, s, p, ltc, light); }
        case SHAPE_SPHERE: { add_sphere(method, select(SPHERE_B, SPHERE_A, a), s, p, ltc, light); }
        default: { add_emitter(method, shape, a, s, p, ltc, light); }
    }
}
