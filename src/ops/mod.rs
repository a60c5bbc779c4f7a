//! Operators, as tables of specs. Each family file exports
//! `pub(crate) const OPS: &[OpDef]`; [`Registry::standard`] concatenates
//! them (the Lua `linit.c` pattern). Adding an operator touches one file.

mod acquire;
mod arith;
mod assemble;
mod assistants;
mod bc;
mod biot;
mod born;
mod calp;
#[cfg(test)]
mod catalogue_tests;
mod chan_cham;
mod chan_comp;
mod chan_supp;
mod chan_support;
mod chargement;
mod chargement_extr;
mod chpo_rigi;
mod cmct;
mod colour;
mod complex_modes;
mod config;
mod contact;
mod coor_field;
mod covariance;
mod curves;
mod damping;
mod dans;
mod date;
mod dofs;
mod elem_containing;
mod elem_field;
mod element_block;
mod empty;
mod evol;
mod evol_extr;
mod evol_extremum;
mod evol_temps;
mod excellence;
mod export;
mod external;
mod extract;
mod fibre_section;
mod fields;
mod fit;
mod flam;
mod fofi;
mod format;
mod fourier;
mod fracture;
mod front;
mod heat;
mod hist;
mod hist_field;
mod hooke;
mod hyperbolic;
mod impact;
mod inclusion;
mod insert;
mod integrate;
mod io;
mod joint_mesh;
mod kp;
mod ksigma;
mod level_set;
mod limits;
mod lists;
mod lists_search;
mod manu;
mod manu_chml_fields;
mod masq;
mod math;
mod mesh;
mod mesh_contours;
mod mesh_cut;
mod mesh_delaunay;
mod mesh_derive;
mod mesh_edit;
mod mesh_fill;
mod mesh_free;
mod mesh_isov;
mod mesh_lines;
mod mesh_moin_geo;
mod mesh_move;
mod mesh_partition;
mod mesh_query;
mod mesh_repair;
mod mesh_ruled;
mod mesh_select;
mod mesh_verify;
mod model;
mod model_mixed;
mod model_zones;
mod move_models;
mod nodal_field;
mod noise;
mod nomc_mchaml;
mod ntab;
mod nuage;
mod objects;
mod objet;
mod opti;
mod opti_own;
mod ordo_cost;
mod orient_check;
mod param_fit;
mod pasapas;
mod pasapas_dyn;
mod pasapas_fields;
mod pasapas_model;
mod pasapas_vary;
mod pica;
mod pica_xfem;
mod poin_field;
mod pointwise;
mod poly_roots;
mod post;
mod pres_chel;
mod pres_field;
mod pres_model;
mod pres_shell;
mod prestress;
mod prim;
mod principal;
mod prob;
mod products;
mod projection;
mod raff;
mod rela_accro;
mod rela_cori;
mod rela_cori_dist;
mod rela_mili;
mod rela_model;
mod replace;
mod reso;
mod restrict;
mod rimp;
mod rtens;
mod rtens_matrix;
mod simplex;
mod special;
mod spectra;
mod superele;
mod surface_forces;
mod symmetry;
mod tables;
mod temps;
mod thermo;
mod thermo_field;
mod transform;
mod triple_product;
mod union;
mod variable;
mod variable_fields;
mod vector_product;
mod vibr;
mod voronoi;
mod vsur;
mod weibull;
mod work;
mod xfem;
mod xfem_model;
mod zero;

// The machine and the argument reader live in `eval`; the families name
// them from here, as they always did.
pub(crate) use crate::eval::args;
pub use crate::eval::args::{ends_window, keyword_matches, take_typed, takes_no_argument, Args, FromArg, Num, PointId};
pub use crate::eval::registry::{op_key, HostFn, OpDef, OpFn, OpSpec, Registry};

/// The standard operators: every family's table, in one registry. Built
/// here because the table of families is what `ops` is; the registry
/// itself belongs to the machine (`eval::registry`).
impl Registry {
    /// Every built-in family.
    pub fn standard() -> Self {
        let mut r = Registry::default();
        for table in [
            arith::OPS,
            math::OPS,
            hyperbolic::OPS,
            lists::OPS,
            noise::OPS,
            covariance::OPS,
            hist::OPS,
            ntab::OPS,
            fourier::OPS,
            date::OPS,
            rimp::OPS,
            fit::OPS,
            excellence::OPS,
            front::OPS,
            param_fit::OPS,
            spectra::OPS,
            weibull::OPS,
            simplex::OPS,
            prob::OPS,
            lists_search::OPS,
            empty::OPS,
            zero::OPS,
            extract::OPS,
            insert::OPS,
            replace::OPS,
            vsur::OPS,
            objects::OPS,
            io::OPS,
            temps::OPS,
            opti::OPS,
            union::OPS,
            mesh::OPS,
            mesh_query::OPS,
            mesh_free::OPS,
            mesh_partition::OPS,
            assistants::OPS,
            external::OPS,
            biot::OPS,
            acquire::OPS,
            mesh_contours::OPS,
            mesh_derive::OPS,
            mesh_delaunay::OPS,
            voronoi::OPS,
            triple_product::OPS,
            dans::OPS,
            inclusion::OPS,
            mesh_isov::OPS,
            mesh_lines::OPS,
            mesh_ruled::OPS,
            joint_mesh::OPS,
            mesh_move::OPS,
            mesh_repair::OPS,
            mesh_edit::OPS,
            transform::OPS,
            colour::OPS,
            config::OPS,
            objet::OPS,
            bc::OPS,
            symmetry::OPS,
            special::OPS,
            calp::OPS,
            contact::OPS,
            pica::OPS,
            chargement::OPS,
            model::OPS,
            kp::OPS,
            damping::OPS,
            complex_modes::OPS,
            prestress::OPS,
            surface_forces::OPS,
            ksigma::OPS,
            vibr::OPS,
            manu::OPS,
            fields::OPS,
            products::OPS,
            masq::OPS,
            born::OPS,
            projection::OPS,
            restrict::OPS,
            reso::OPS,
            post::OPS,
            thermo::OPS,
            heat::OPS,
            mesh_verify::OPS,
            hooke::OPS,
            principal::OPS,
            rtens::OPS,
            integrate::OPS,
            superele::OPS,
            cmct::OPS,
            fracture::OPS,
            level_set::OPS,
            xfem::OPS,
            export::OPS,
            evol::OPS,
            curves::OPS,
            nuage::OPS,
            tables::OPS,
            variable::OPS,
            pasapas::OPS,
            prim::OPS,
            flam::OPS,
            raff::OPS,
            chpo_rigi::OPS,
            work::OPS,
            fofi::OPS,
            poly_roots::OPS,
            orient_check::OPS,
        ] {
            for d in table {
                r.insert(OpSpec::from(d));
            }
        }
        r
    }
}
