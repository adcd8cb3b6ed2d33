//! The 4D table out to engines (docs/design.md §2.9, `lut --export aniso-texture`): three
//! RGBA32F 3D textures, and a WGSL lookup that reads them as `shaders/ltc_aniso.wgsl` reads
//! the lab's buffer.
//!
//! Texture `r` (0, 1, 2) holds the `r`-th vec4 of each node (`gpu::ltc_aniso::pack_aniso`'s
//! `[m00 m01 m02 m10] [m11 m12 m20 m21] [m22 norm fresnel 0]`, the stored matrix by rows) at
//! texel `(a, b, t + Nt·p)`: width Na (α_x's axis), height Nb (α_y's), depth Nt·Np (θo's
//! axis within each of φo's slabs). The file holds the three volumes one after another,
//! each by x fastest, then y, then z, little-endian f32.

use crate::ltc::aniso::AnisoLut;

/// The exported texture file's name.
pub const TEXTURE_FILE: &str = "ltc_aniso.bin";
/// The exported lookup's name.
pub const WGSL_FILE: &str = "ltc_aniso.wgsl";

/// vec4s a node (`pack_aniso`'s three): one texture each.
pub const TEXTURES: usize = 3;

/// The node counts of each texture: `[width, height, depth]`.
pub fn texture_size(lut: &AnisoLut) -> [usize; 3] {
    let [na, nb, nt, np] = lut.dims;
    [na, nb, nt * np]
}

/// The three volumes' bytes, as the module's header lays them out.
pub fn texture_bytes(lut: &AnisoLut) -> Vec<u8> {
    let packed = super::pack_aniso(lut);
    // pack_aniso's node order ((p·Nt + t)·Nb + b)·Na + a is the texel order (x = a, y = b,
    // z = t + Nt·p) already; only the three vec4s of a node go to three volumes.
    (0..TEXTURES)
        .flat_map(|r| packed.iter().skip(r).step_by(TEXTURES))
        .flat_map(|texel| texel.iter().flat_map(|x| x.to_le_bytes()))
        .collect()
}

/// The texels back from `bytes`: `[volume][node]`, each node's vec4 (the test's decoder,
/// and an engine's in four lines).
pub fn read_texels(bytes: &[u8], nodes: usize) -> Option<Vec<Vec<[f32; 4]>>> {
    if bytes.len() != TEXTURES * nodes * 16 {
        return None;
    }
    let floats: Vec<f32> = bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    let texels: Vec<[f32; 4]> = floats
        .chunks_exact(4)
        .map(|t| [t[0], t[1], t[2], t[3]])
        .collect();
    Some(texels.chunks(nodes).map(<[_]>::to_vec).collect())
}

/// The lookup: `header` as comments, the table's constants, the three textures' bindings
/// (group 0, bindings 0–2), and `shaders/ltc_aniso.wgsl` with its buffer reads made
/// texture loads. Call `aniso_ltc(ltc_aniso_table(), vec2(α_x, α_y), v)` with `v` the unit
/// view in the tangent frame.
pub fn wgsl(lut: &AnisoLut, header: &str) -> String {
    let [na, nb, nt, np] = lut.dims;
    let (axes, _) = super::axes_constant(lut.axes);
    let (stored, _) = super::stored_constant(lut.stored);
    let mut out = String::new();
    for line in header.lines() {
        out.push_str(&format!("// {line}\n"));
    }
    out.push_str(&format!(
        "// {TEXTURE_FILE}: three RGBA32F 3D textures of {na}×{nb}×{} texels, {} bytes: texel (a, b, t + {nt}·p)\n// of texture r holds the r-th vec4 of node (a, b, t, p).\n\n",
        nt * np,
        TEXTURES * lut.cells.len() * 16,
    ));
    out.push_str(BINDINGS);
    out.push_str(&format!(
        "fn ltc_aniso_table() -> AnisoTable {{\n    return AnisoTable(0u, vec4<u32>({na}u, {nb}u, {nt}u, {np}u), {axes}u, {stored}u);\n}}\n\n"
    ));
    out.push_str(&lookup_source());
    out
}

/// `shaders/ltc_aniso.wgsl` reading three textures instead of the lab's buffer, after what it
/// uses of the modules it is composed after: `PI` (brdf.wgsl), `Ltc` (ltc.wgsl),
/// `atan_precise` and `acos_precise` (sphere_light.wgsl). A change to the buffer's read there fails the export's test (the
/// replaced text must be found).
pub fn lookup_source() -> String {
    let pi = "const PI: f32 = 3.141592653589793;\n\n";
    let sphere = crate::gpu::light::sphere_light::SOURCE;
    let atan = item_text(sphere, "fn atan_precise(");
    let acos = item_text(sphere, "fn acos_precise(");
    let ltc = item_text(crate::gpu::ltc::SOURCE, "struct Ltc {");
    format!(
        "{pi}{ltc}\n{atan}\n{acos}\n{}",
        super::SOURCE.replace(BUFFER_READ, TEXTURE_READ)
    )
}

/// The item of WGSL `source` that starts with the line `head` (a function's or a struct's),
/// with the comment lines just above it, to its closing brace at a line's start (empty
/// where it is not there, which the export's test finds).
fn item_text(source: &str, head: &str) -> String {
    let Some(at) = source.find(&format!("\n{head}")) else {
        return String::new();
    };
    let end = source[at..]
        .find("\n}\n")
        .map_or(source.len(), |e| at + e + 3);
    let start = source[..at].rfind("\n\n").map_or(0, |c| c + 2);
    source[start..end].to_string()
}

/// The buffer read of `aniso_sample` in `shaders/ltc_aniso.wgsl`.
pub const BUFFER_READ: &str =
    "        let node = ((k.w * t.dims.z + k.z) * t.dims.y + k.y) * t.dims.x + k.x;
        let at = t.base + node * ANISO_VEC4S_PER_NODE;
        rows[0] += w * lut[at];
        rows[1] += w * lut[at + 1u];
        rows[2] += w * lut[at + 2u];";

/// The same read from the three textures.
const TEXTURE_READ: &str =
    "        let texel = vec3<i32>(i32(k.x), i32(k.y), i32(k.z + t.dims.z * k.w));
        rows[0] += w * textureLoad(ltc_aniso_0, texel, 0);
        rows[1] += w * textureLoad(ltc_aniso_1, texel, 0);
        rows[2] += w * textureLoad(ltc_aniso_2, texel, 0);";

/// The three textures' bindings.
const BINDINGS: &str = "@group(0) @binding(0) var ltc_aniso_0: texture_3d<f32>;
@group(0) @binding(1) var ltc_aniso_1: texture_3d<f32>;
@group(0) @binding(2) var ltc_aniso_2: texture_3d<f32>;

";

/// What the export's header says of the table.
pub fn describe(lut: &AnisoLut) -> String {
    format!(
        "4D LTC table for anisotropic GGX (ltc-lab), axes {}, stored {}, {:?} nodes (α_x, α_y, θo, φo): docs/design.md §2.9 of ltc-lab decodes both",
        lut.axes.name(),
        lut.stored.name(),
        lut.dims
    )
}
