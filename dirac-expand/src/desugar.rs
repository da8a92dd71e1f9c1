//! What a model's attributes are written into before it is checked: a URDF robot's bodies and
//! joints, and each set-valued law's mode, row and events.

use crate::ast::Model;
use crate::ctxt::Ctxt;

/// Reads `input`'s model ([`Model::from_input`]) and writes its URDF robot and its laws into
/// its items.
pub fn read<'a>(cx: &Ctxt, input: &'a syn::DeriveInput) -> Model<'a> {
    let mut model = Model::from_input(cx, input);
    if let Some(path) = model.urdf.clone().filter(|_| !model.incomplete) {
        crate::urdf::desugar(cx, &mut model, &path);
    } else if let Some(key) = &model.joint_limits {
        cx.error_spanned_by(key, "`joint_limits` are a URDF file's: add `urdf = \"robot.urdf\"`");
    }
    crate::laws::desugar(cx, &mut model);
    model
}
