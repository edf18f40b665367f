// Present so that [build-dependencies] take part in the host's feature
// unification; it builds nothing.
fn main() {}
