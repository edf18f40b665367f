//! `weft serve`'s integration tests, one binary: the HTTP surface and the
//! watcher (`server`), and hostile clients (`hostile`).

mod hostile;
mod server;
