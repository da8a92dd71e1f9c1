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
    } else if model.urdf.is_none() {
        let keys = [
            &model.joint_limits,
            &model.floating,
            &model.gravity.as_ref().map(|(key, _)| key.clone()),
            &model.ground.as_ref().map(|ground| ground.key.clone()),
        ];
        for key in keys.into_iter().flatten() {
            cx.error_spanned_by(key, format!("`{key}` is a URDF robot's: add `urdf = \"robot.urdf\"`"));
        }
    }
    crate::laws::desugar(cx, &mut model);
    model
}
