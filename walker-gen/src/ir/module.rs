//! What one generated file declares: its kernels ([`Kernel`], with a result [`Shape`]), its
//! runtime parameters ([`ParamDecl`]) and the [`Module`] that holds them with the graph.

use walker_scene::model::fields::param_fields;

use super::graph::Graph;
use super::node::{NodeId, ParamId, index_u32};

/// The shape of a kernel's result.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Shape {
    /// One value, returned as `F`.
    Scalar,
    /// `n` values, returned as `[F; n]`.
    Vector(usize),
    /// `r x c` values in row-major order, returned as `[[F; c]; r]`.
    Matrix(usize, usize),
}

impl Shape {
    /// The number of outputs the shape holds.
    #[must_use]
    pub fn len(self) -> usize {
        match self {
            Shape::Scalar => 1,
            Shape::Vector(n) => n,
            Shape::Matrix(r, c) => r * c,
        }
    }

    /// Whether the shape holds no values.
    #[must_use]
    pub fn is_empty(self) -> bool {
        self.len() == 0
    }
}

/// One generated function: named outputs of the graph as functions of `args` and the parameters.
#[derive(Clone, Debug)]
pub struct Kernel {
    /// Function name (a Rust identifier), for example `lambda_level`.
    pub name: String,
    /// What the kernel computes (first line of its doc comment).
    pub doc: String,
    /// The paper equations it implements, for example `"Eqs. 22-23"`.
    pub equation: String,
    /// Argument names in signature order; every [`Node::Input`](crate::Node::Input) the outputs use must be here.
    pub args: Vec<String>,
    /// Output names (for the docs) and their nodes, row-major for matrices.
    pub outputs: Vec<(String, NodeId)>,
    /// How the outputs are returned.
    pub output_shape: Shape,
}

/// A runtime parameter of a [`Module`]: a field of the generated `Params`
/// ([`Module::param_field`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParamDecl {
    /// Name as in the scene (`m1`, `I1`, `T_set`).
    pub name: String,
    /// Doc comment of the field.
    pub doc: String,
}

/// Everything that goes into one generated file.
#[derive(Clone, Debug, Default)]
pub struct Module {
    /// The expression graph shared by all kernels.
    pub graph: Graph,
    /// Runtime parameters, in `Params` field order.
    pub params: Vec<ParamDecl>,
    /// The kernels, in file order.
    pub kernels: Vec<Kernel>,
    /// The scene name, for the `@generated` line.
    pub scene_name: String,
    /// Extra lines for the file's header comment (structure, fixed values...).
    pub notes: Vec<String>,
    /// How a kernel is evaluated, where the generator chose between forms (a model's stance
    /// and impact kernels: closed form or structured solve, by operation count), by kernel
    /// name; for example `structured solve (closed form: 913 ops)`.
    pub forms: std::collections::BTreeMap<String, String>,
}

impl Module {
    /// An empty module for scene `scene_name`.
    #[must_use]
    pub fn new(scene_name: &str) -> Self {
        Module {
            scene_name: scene_name.to_owned(),
            ..Module::default()
        }
    }

    /// Declares the runtime parameter `name` (or finds it, if already declared).
    pub fn declare_param(&mut self, name: &str, doc: &str) -> ParamId {
        if let Some(i) = self.params.iter().position(|p| p.name == name) {
            return ParamId(index_u32(i));
        }
        self.params.push(ParamDecl {
            name: name.to_owned(),
            doc: doc.to_owned(),
        });
        ParamId(index_u32(self.params.len() - 1))
    }

    /// The Rust field of parameter `index` in the generated `Params`: its name in ASCII lower
    /// case, unless another parameter shares that lower case
    /// ([`walker_scene::model::fields`]); `param{index}` for an undeclared index.
    #[must_use]
    pub fn param_field(&self, index: usize) -> String {
        let names: Vec<&str> = self.params.iter().map(|p| p.name.as_str()).collect();
        param_fields(&names)
            .into_iter()
            .nth(index)
            .unwrap_or_else(|| format!("param{index}"))
    }

    /// Declares the runtime parameter `name` and returns its node.
    pub fn param(&mut self, name: &str, doc: &str) -> NodeId {
        let id = self.declare_param(name, doc);
        self.graph.param(id)
    }

    /// The index of the kernel called `name`.
    #[must_use]
    pub fn kernel(&self, name: &str) -> Option<&Kernel> {
        self.kernels.iter().find(|k| k.name == name)
    }
}
