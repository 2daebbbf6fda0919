//! The `asperity` command line. A thin layer: parsing, printing, exit codes.
fn main() {}
