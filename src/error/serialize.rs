//! [`Args`] for JS: a message's arguments as a plain object `{ name: value }` (built only where
//! serde is: the wasm bindings, or the `serde` feature). Tested where it is used: in the browser,
//! by tests/bindings.rs (an error's `details.args`), and in Node by tests/node/messages.test.mjs.

use super::{Arg, Args};

impl serde::Serialize for Args {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        // a struct, so that JS gets a plain object (serde-wasm-bindgen writes maps as Map)
        use serde::ser::SerializeStruct;
        let mut object = serializer.serialize_struct("Args", self.0.len())?;
        for (name, value) in &self.0 {
            match value {
                Arg::Text(s) => object.serialize_field(name, s)?,
                Arg::Number(x) => object.serialize_field(name, x)?,
            }
        }
        object.end()
    }
}
