//! Elements, quadrature and assembly: knows meshes and materials, never the language.
pub mod mesh;
pub mod meshing;
