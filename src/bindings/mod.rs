//! Bindings: the layer that ties the Euler-top model to the claim engine.  It sits above
//! both (the model knows nothing of claims, the engine nothing of the Euler top) and
//! registers the model's functions under the names the catalogue uses.

mod ball;
pub mod catalogue;
pub mod euler_top;
mod implicit;
mod implicit_series;
