//! Pictures on lavapipe: every material's golden renders, the outline and
//! fringe-shadow passes, the character textures, the shipped and glTF scenes
//! (with the glTF BRDF checks), and the live inspector in headless Chromium.
//! With no Vulkan adapter these tests fail with what to install; they never
//! skip.

mod fringe_shadow;
mod gltf_brdf;
mod gltf_iridescence;
mod gltf_scenes;
mod inspector;
mod outline;
mod render;
mod scenes;
mod textures;
