//! Each method's work per light, counted from the plane shader as built (docs/design.md
//! §4.10): naga's IR of the function that adds one light (`add_brdf`, `add_ltc_fast`, …) and
//! of everything it calls, as the `eq30` pipeline specializes it. Counted statically: an
//! expression once where it is emitted, a branch whose condition is a pipeline constant by its
//! taken side, any other branch by both sides except one that returns (an early exit, which a
//! light that reaches the sum does not take), a loop's body once.

use std::collections::HashMap;

// wgpu's own naga (the one that compiles the shaders), with its WGSL front end, on the
// desktop and in the browser alike.
use wgpu::naga;
use wgpu::naga::{BinaryOperator, Expression, Handle, MathFunction, Statement, TypeInner};

use crate::render::Method;

/// Operations per light, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Scalar additions, subtractions, multiplications and the like (min, max, abs, select,
    /// conversions): a vector's per component, `dot` and a matrix times a vector as their
    /// multiply-adds.
    pub arithmetic: u32,
    /// Scalar divisions.
    pub divisions: u32,
    /// Square roots, inverse square roots and transcendental functions (a `length` or
    /// `normalize` holds one).
    pub special: u32,
    /// Loads from memory outside the function (the uniforms, the tables, workgroup memory).
    pub reads: u32,
}

impl Work {
    /// Its operations as one count, for a submission's estimate (`gpu::failures::submissions`): a
    /// division or a special function as 8 and a read as 4. A streaming multiprocessor of
    /// compute capability 8.x–9.0 gives 128 f32 additions or multiplications a clock but 16
    /// reciprocals, square roots or transcendentals (the CUDA C++ Programming Guide's table
    /// of arithmetic instruction throughput); a read from the caches is a few times an add.
    pub fn operations(&self) -> f64 {
        f64::from(self.arithmetic)
            + 8.0 * f64::from(self.divisions + self.special)
            + 4.0 * f64::from(self.reads)
    }
}

impl std::ops::Add for Work {
    type Output = Self;
    fn add(self, b: Self) -> Self {
        Self {
            arithmetic: self.arithmetic + b.arithmetic,
            divisions: self.divisions + b.divisions,
            special: self.special + b.special,
            reads: self.reads + b.reads,
        }
    }
}

/// The function of plane.wgsl (or ltc_f16.wgsl) that adds one light by `method`, and how many
/// lights one call adds.
pub fn light_function(method: Method) -> (&'static str, u32) {
    match method {
        Method::Brdf => ("add_brdf", 1),
        Method::BrdfFast => ("add_brdf_fast", 1),
        Method::Ltc => ("add_ltc", 1),
        Method::LtcFast => ("add_ltc_fast", 1),
        Method::LtcF16 => ("add_ltc_f16", 1),
        Method::LtcF16Pairs => ("add_ltc_f16_pair", 2),
        // The file's own function for a point (method_file.wgsl calls it for each light).
        Method::File => ("method_point", 1),
    }
}

/// Each method's work per light in the plane shader (with the f16 forms: its f16 module).
pub fn work_per_light() -> Result<Vec<(Method, Work)>, String> {
    let source = super::plane_module_source(true);
    // The lab's own methods: the file's work is `file_work`'s.
    Method::F32
        .into_iter()
        .chain(Method::F16)
        .map(|m| {
            let (name, lights) = light_function(m);
            let w = work_of(&source, name)?;
            let per = |x: u32| x.div_ceil(lights);
            Ok((
                m,
                Work {
                    arithmetic: per(w.arithmetic),
                    divisions: per(w.divisions),
                    special: per(w.special),
                    reads: per(w.reads),
                },
            ))
        })
        .collect()
}

/// A method file's work per light (docs/design.md §5.13): each function it has, counted in
/// the plane shader as composed with it (its loop guards included: a loop's body is counted
/// once, as for the lab's own), by shape name.
pub fn file_work(
    file: &crate::gpu::method_file::MethodFile,
) -> Result<Vec<(&'static str, Work)>, String> {
    let source = super::plane_module_source_with(false, Some(file));
    crate::light::ShapeKind::ALL
        .into_iter()
        .filter(|&k| file.shades(k))
        .map(|k| {
            Ok((
                k.name(),
                work_of(&source, &crate::gpu::method_file::entry(k).0)?,
            ))
        })
        .collect()
}

/// The estimated operations of one light at one pixel in the plane module with `file` (or
/// none), for splitting a render into submissions (`gpu::failures::submissions`): `add_light` and all it
/// may call (every shape's methods, each side's: counted twice), and, with a file, its largest
/// function again at its whole loop budget (`method_file::STEPS` steps, each at most its
/// function's whole work, as a loop body is counted once).
pub fn light_operations(file: Option<&crate::gpu::method_file::MethodFile>) -> Result<f64, String> {
    let source = super::plane_module_source_with(false, file);
    let lab = 2.0 * work_of(&source, "add_light")?.operations();
    let worst = match file {
        Some(f) => file_work(f)?
            .iter()
            .map(|(_, w)| w.operations())
            .fold(0.0, f64::max),
        None => 0.0,
    };
    Ok(lab + worst * f64::from(crate::gpu::method_file::STEPS))
}

/// A method file's work per light in words, a shape after another (`point: 85 arithmetic,
/// 8 divisions, 1 special, 0 reads`), or why it could not be counted.
pub fn file_work_line(file: &crate::gpu::method_file::MethodFile) -> String {
    match file_work(file) {
        Ok(work) => work
            .iter()
            .map(|(shape, w)| {
                format!(
                    "{shape}: {} arithmetic, {} divisions, {} special, {} reads",
                    w.arithmetic, w.divisions, w.special, w.reads
                )
            })
            .collect::<Vec<_>>()
            .join("; "),
        Err(e) => format!("not counted ({e})"),
    }
}

/// The work of the WGSL function `name` of `source` and of everything it calls.
pub fn work_of(source: &str, name: &str) -> Result<Work, String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .map_err(|e| format!("{e:?}"))?;
    let f = module
        .functions
        .iter()
        .find(|(_, f)| f.name.as_deref() == Some(name))
        .map(|(h, _)| h)
        .ok_or(format!("no function {name}"))?;
    let mut counter = Counter {
        module: &module,
        info: &info,
        done: HashMap::new(),
    };
    Ok(counter.function(f))
}

/// A constant value of the eq30 pipeline.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Value {
    Bool(bool),
    U32(u32),
}

/// `a && b` (`decides` false) or `a || b` (`decides` true) where each side may be unknown: a
/// side equal to `decides` settles it whatever the other; two known sides give the other value.
fn short_circuit(a: Option<Value>, b: Option<Value>, decides: bool) -> Option<Value> {
    match (a, b) {
        (Some(Value::Bool(x)), _) | (_, Some(Value::Bool(x))) if x == decides => {
            Some(Value::Bool(decides))
        }
        (Some(Value::Bool(_)), Some(Value::Bool(_))) => Some(Value::Bool(!decides)),
        _ => None,
    }
}

struct Counter<'a> {
    module: &'a naga::Module,
    info: &'a naga::valid::ModuleInfo,
    done: HashMap<Handle<naga::Function>, Work>,
}

impl Counter<'_> {
    /// A function's work, its callees' included.
    fn function(&mut self, f: Handle<naga::Function>) -> Work {
        if let Some(&w) = self.done.get(&f) {
            return w;
        }
        let w = self.block(f, &self.module.functions[f].body);
        self.done.insert(f, w);
        w
    }

    fn block(&mut self, f: Handle<naga::Function>, block: &naga::Block) -> Work {
        let mut w = Work::default();
        for s in block {
            w = w + self.statement(f, s);
        }
        w
    }

    fn statement(&mut self, f: Handle<naga::Function>, s: &Statement) -> Work {
        match s {
            Statement::Emit(range) => range
                .clone()
                .map(|e| self.expression(f, e))
                .fold(Work::default(), std::ops::Add::add),
            Statement::Block(b) => self.block(f, b),
            Statement::If {
                condition,
                accept,
                reject,
            } => match self.constant(f, *condition) {
                Some(Value::Bool(true)) => self.block(f, accept),
                Some(Value::Bool(false)) => self.block(f, reject),
                _ => {
                    let side = |c: &mut Self, b: &naga::Block| {
                        let exits = matches!(b.last(), Some(Statement::Return { .. }));
                        if exits {
                            Work::default()
                        } else {
                            c.block(f, b)
                        }
                    };
                    side(self, accept) + side(self, reject)
                }
            },
            Statement::Switch { cases, .. } => cases
                .iter()
                .map(|c| self.block(f, &c.body))
                .fold(Work::default(), std::ops::Add::add),
            Statement::Loop {
                body, continuing, ..
            } => self.block(f, body) + self.block(f, continuing),
            Statement::Call { function, .. } => self.function(*function),
            _ => Work::default(),
        }
    }

    /// The scalar components of an expression's value.
    fn components(&self, f: Handle<naga::Function>, e: Handle<Expression>) -> u32 {
        match self.info[f][e].ty.inner_with(&self.module.types) {
            TypeInner::Vector { size, .. } => *size as u32,
            TypeInner::Matrix { columns, rows, .. } => *columns as u32 * *rows as u32,
            _ => 1,
        }
    }

    fn expression(&mut self, f: Handle<naga::Function>, e: Handle<Expression>) -> Work {
        let exprs = &self.module.functions[f].expressions;
        let n = self.components(f, e);
        let arithmetic = |arithmetic| Work {
            arithmetic,
            ..Work::default()
        };
        match &exprs[e] {
            Expression::Binary { op, left, right } => match op {
                BinaryOperator::Add | BinaryOperator::Subtract => arithmetic(n),
                BinaryOperator::Multiply => {
                    let ty =
                        |x: Handle<Expression>| self.info[f][x].ty.inner_with(&self.module.types);
                    match (ty(*left), ty(*right)) {
                        // r × c multiplies and r × (c − 1) additions.
                        (TypeInner::Matrix { columns, rows, .. }, TypeInner::Vector { .. }) => {
                            let (c, r) = (*columns as u32, *rows as u32);
                            arithmetic(r * (2 * c - 1))
                        }
                        _ => arithmetic(n),
                    }
                }
                BinaryOperator::Divide | BinaryOperator::Modulo => Work {
                    divisions: n,
                    ..Work::default()
                },
                _ => Work::default(),
            },
            Expression::Math { fun, arg, .. } => self.math(*fun, self.components(f, *arg), n),
            Expression::Select { .. }
            | Expression::As {
                convert: Some(_), ..
            } => arithmetic(n),
            Expression::Load { pointer } if self.global(f, *pointer) => Work {
                reads: 1,
                ..Work::default()
            },
            _ => Work::default(),
        }
    }

    /// A math function's work on an argument of `arg` components giving `n`.
    fn math(&self, fun: MathFunction, arg: u32, n: u32) -> Work {
        use MathFunction as M;
        let (arithmetic, special) = match fun {
            M::Dot => (2 * arg - 1, 0),
            M::Cross => (9, 0),
            M::Length => (2 * arg - 1, 1),
            // A subtraction or a multiply per component more than `length`.
            M::Distance | M::Normalize => (3 * arg - 1, 1),
            M::Clamp | M::Fma => (2 * n, 0),
            M::Mix => (3 * n, 0),
            M::Sqrt
            | M::InverseSqrt
            | M::Exp
            | M::Exp2
            | M::Log
            | M::Log2
            | M::Pow
            | M::Sin
            | M::Cos
            | M::Tan
            | M::Asin
            | M::Acos
            | M::Atan
            | M::Atan2 => (0, n),
            M::Transpose => (0, 0),
            _ => (n, 0),
        };
        Work {
            arithmetic,
            special,
            ..Work::default()
        }
    }

    /// Whether a pointer leads to a global variable (memory outside the function).
    fn global(&self, f: Handle<naga::Function>, mut p: Handle<Expression>) -> bool {
        let exprs = &self.module.functions[f].expressions;
        loop {
            match &exprs[p] {
                Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => p = *base,
                Expression::GlobalVariable(_) => return true,
                _ => return false,
            }
        }
    }

    /// An expression's value where the eq30 pipeline fixes it (literals, constants and the
    /// override constants at their defaults: eq30's horizon, point lights, table A).
    fn constant(&self, f: Handle<naga::Function>, e: Handle<Expression>) -> Option<Value> {
        let exprs = &self.module.functions[f].expressions;
        self.value(&exprs[e], &|h| self.constant(f, h))
    }

    fn global_constant(&self, e: Handle<Expression>) -> Option<Value> {
        self.value(&self.module.global_expressions[e], &|h| {
            self.global_constant(h)
        })
    }

    fn value(
        &self,
        e: &Expression,
        operand: &dyn Fn(Handle<Expression>) -> Option<Value>,
    ) -> Option<Value> {
        match e {
            Expression::Literal(naga::Literal::Bool(b)) => Some(Value::Bool(*b)),
            Expression::Literal(naga::Literal::U32(u)) => Some(Value::U32(*u)),
            Expression::Constant(c) => self.global_constant(self.module.constants[*c].init),
            Expression::Override(o) => self.global_constant(self.module.overrides[*o].init?),
            Expression::Unary {
                op: naga::UnaryOperator::LogicalNot,
                expr,
            } => match operand(*expr)? {
                Value::Bool(b) => Some(Value::Bool(!b)),
                Value::U32(_) => None,
            },
            Expression::Binary { op, left, right } => {
                let (a, b) = (operand(*left), operand(*right));
                match op {
                    BinaryOperator::Equal => Some(Value::Bool(a? == b?)),
                    BinaryOperator::NotEqual => Some(Value::Bool(a? != b?)),
                    BinaryOperator::LogicalAnd => short_circuit(a, b, false),
                    BinaryOperator::LogicalOr => short_circuit(a, b, true),
                    _ => None,
                }
            }
            _ => None,
        }
    }
}
