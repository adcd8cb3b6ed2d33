//! A method file checked against the device that will run it (docs/design.md §5.13): its text
//! with the device's own shader capabilities (naga's, from the device's features and downlevel
//! flags, as wgpu maps them), and the plane module composed with it in every variant the device
//! builds — with the f16 methods where it has SHADER_F16, and without (its work is counted
//! there). A file reads as WGSL with every capability naga knows (`MethodFile::from_source`);
//! what the device lacks is refused here, at the file's line and column, in words.

use wgpu::naga::valid::Capabilities;

use super::wgsl_text::{TokenKind, tokens};
use super::{MethodFile, check, interface, place};
use crate::error::Result;
use crate::gpu::GpuContext;

/// What a device's shaders take: naga's capabilities and whether its plane module has the
/// f16 methods (`enable f16;` at its top).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DeviceShaders {
    pub capabilities: Capabilities,
    pub f16: bool,
}

/// A capability a method file's functions could ask for: the device feature that grants it
/// (`wgpu_naga_bridge::features_to_naga_capabilities`), what in WGSL asks for it, and the
/// words and literal suffixes that ask (to place the refusal where naga gives only the
/// function).
struct Need {
    capability: Capabilities,
    feature: &'static str,
    words: &'static str,
    names: &'static [&'static str],
    suffixes: &'static [&'static str],
}

/// The capabilities a function can ask for; the rest concern bindings, textures and entry
/// points, which a file cannot declare.
const NEEDS: [Need; 7] = [
    Need {
        capability: Capabilities::FLOAT64,
        feature: "SHADER_F64",
        words: "`f64`",
        names: &["f64"],
        suffixes: &["lf"],
    },
    Need {
        capability: Capabilities::SHADER_INT64,
        feature: "SHADER_INT64",
        words: "`i64` and `u64`",
        names: &["i64", "u64"],
        suffixes: &["li", "lu"],
    },
    Need {
        capability: Capabilities::SHADER_INT16,
        feature: "SHADER_I16",
        words: "`i16` and `u16`",
        names: &["i16", "u16"],
        suffixes: &[],
    },
    Need {
        capability: Capabilities::SHADER_FLOAT16,
        feature: "SHADER_F16",
        words: "`f16`",
        names: &["f16"],
        suffixes: &["h"],
    },
    Need {
        capability: Capabilities::SHADER_FLOAT16_IN_FLOAT32,
        feature: "the downlevel flag SHADER_F16_IN_F32",
        words: "packing and unpacking halves",
        names: &["pack2x16float", "unpack2x16float", "quantizeToF16"],
        suffixes: &[],
    },
    Need {
        capability: Capabilities::SUBGROUP,
        feature: "SUBGROUP",
        words: "subgroup operations",
        names: &[
            "subgroupAdd",
            "subgroupBroadcast",
            "subgroupBallot",
            "subgroupMax",
            "subgroupMin",
        ],
        suffixes: &[],
    },
    Need {
        capability: Capabilities::SUBGROUP_BARRIER,
        feature: "SUBGROUP_BARRIER",
        words: "`subgroupBarrier`",
        names: &["subgroupBarrier"],
        suffixes: &[],
    },
];

impl Need {
    /// Where `source` first asks for it: a name, or a literal with its suffix.
    fn first_use(&self, source: &str) -> Option<usize> {
        tokens(source)
            .into_iter()
            .find(|t| match t.kind {
                TokenKind::Ident => self.names.contains(&t.text),
                TokenKind::Number => self.suffixes.iter().any(|s| {
                    t.text.ends_with(s) && !t.text.starts_with("0x") && !t.text.starts_with("0X")
                }),
                TokenKind::Punct => false,
            })
            .map(|t| t.start)
    }
}

impl DeviceShaders {
    /// The shaders of `ctx`'s device.
    pub fn of(ctx: &GpuContext) -> DeviceShaders {
        DeviceShaders {
            capabilities: wgpu_naga_bridge::features_to_naga_capabilities(
                ctx.device.features(),
                ctx.downlevel,
            ),
            f16: ctx.has_f16(),
        }
    }
}

impl MethodFile {
    /// Refuses what `device` cannot run: a construct needing a capability it lacks (named, with
    /// the feature that grants it), at its line and column; or a composed variant its
    /// validation refuses.
    pub fn check_for(&self, device: &DeviceShaders) -> Result<()> {
        let beside = format!("{}\n{}", self.source, interface());
        if let Err(e) = check(&self.name, &self.source, &beside, device.capabilities) {
            return Err(match missing(&self.name, &beside, device.capabilities) {
                Some(need) => {
                    let message = format!(
                        "{} needs {}, which this device does not have",
                        need.words, need.feature
                    );
                    // Where the file asks for it, else where naga placed the error.
                    let at = need.first_use(&self.source);
                    let naga_place = e
                        .message
                        .split(": ")
                        .next()
                        .filter(|p| p.starts_with("line"));
                    match (at, naga_place) {
                        (Some(at), _) => place(&self.name, &self.source, Some(at), message),
                        (None, Some(p)) => crate::error::Error {
                            message: format!("{p}: {message}"),
                            ..e
                        },
                        (None, None) => crate::error::Error { message, ..e },
                    }
                }
                None => e,
            });
        }
        for f16 in [false, true].into_iter().filter(|&f| !f || device.f16) {
            let composed = crate::gpu::plane_module_source_with(f16, Some(self));
            check(&self.name, "", &composed, device.capabilities).map_err(|e| {
                crate::error::Error {
                    message: format!(
                        "the lab could not compose it with its shader{}: {}",
                        if f16 { " (with its f16 methods)" } else { "" },
                        e.message
                    ),
                    ..e
                }
            })?;
        }
        Ok(())
    }
}

/// The first capability of `NEEDS` that, added to `has`, lets `text` validate.
fn missing(name: &str, text: &str, has: Capabilities) -> Option<&'static Need> {
    NEEDS
        .iter()
        .filter(|n| !has.contains(n.capability))
        .find(|n| check(name, "", text, has | n.capability).is_ok())
}

/// What every device gets checked against in a test without one: `naga` alone.
#[cfg(test)]
mod tests {
    use super::*;

    const F64: &str = "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {\n    let x: f64 = 1.0lf;\n    return MethodRadiance(vec3<f32>(f32(x)), vec3<f32>(0.0));\n}\n";

    fn device(capabilities: Capabilities) -> DeviceShaders {
        DeviceShaders {
            capabilities,
            f16: false,
        }
    }

    /// `f64` reads as WGSL, and a device without SHADER_F64 refuses it at its line, naming
    /// the feature; one with it takes it.
    #[test]
    fn a_feature_the_device_lacks_is_refused_at_its_line() {
        let file = MethodFile::from_source("f64.wgsl", F64).unwrap();
        let e = file.check_for(&device(Capabilities::empty())).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        let text = e.to_string();
        assert!(text.contains("f64.wgsl"), "{text}");
        assert!(text.contains("line 2"), "{text}");
        assert!(
            text.contains("`f64` needs SHADER_F64, which this device does not have"),
            "{text}"
        );
        file.check_for(&device(Capabilities::FLOAT64)).unwrap();
    }
}
