//! Decompression bombs against weft's two PNG decoders (issue 28, "Unbounded
//! memory"): `weft_front::texture_files::decode_png` (texture files named by
//! materials, `file = ...`) and `weft_render::decode_png` (`weft preview
//! --texture NAME=file.png`).
//!
//! Each PNG here is a valid 1x1 image of a few megabytes at most that carries
//! a zlib stream of zeros inflating to about a gigabyte: in an iCCP chunk (a
//! colour profile weft never uses), in zTXt and iTXt chunks, and as the image
//! data itself (far more than the 1x1 image needs). Each decoder must give the
//! pixel back, promptly, while the process's peak resident set grows by far
//! less than the stream would inflate to.
//!
//! Without `set_ignore_iccp_chunk(true)` the png crate (0.18) inflates an
//! iCCP chunk up to the decoder's allocation limit: the peak grows by 129 MiB
//! for texture files and 513 MiB for `--texture` (measured with the call
//! removed), and this test fails. png 0.18 keeps zTXt/iTXt compressed unless
//! asked to inflate them, and stops reading image data once the image is
//! full, so those three cases pass even without the decoders' settings: they
//! guard against a decoder (or png version) that inflates them eagerly.
//!
//! The peak is the process's `VmHWM`, reset through `/proc/self/clear_refs`
//! before each decode; everything runs in the one test below, so no other
//! test in this binary can raise it meanwhile.

use std::time::{Duration, Instant};

/// Bytes the bombs' zlib streams inflate to (about 1 GiB).
const INFLATED: u64 = 1 << 30;

/// Peak resident growth a decode of a 1x1 image may cause: the input (a few
/// MiB) and the decoder's buffers. The iCCP bomb without `ignore_iccp_chunk`
/// grows it by 129 MiB or more.
const MAX_GROWTH_KIB: u64 = 48 << 10;

/// A zlib stream of `INFLATED` zero bytes, prefixed by `prefix`, built
/// without inflating it: flate2 compresses the prefix and one 1 MiB run of
/// zeros, sync-flushing after each (so each piece ends on a byte boundary
/// with its blocks complete); the second run's bytes, which refer back only
/// to zeros, are then repeated. The Adler-32 is computed for the whole.
fn zlib_of_zeros(prefix: &[u8]) -> Vec<u8> {
    use flate2::{Compress, Compression, FlushCompress};
    const RUN: usize = 1 << 20;
    let mut c = Compress::new(Compression::best(), false);
    let mut piece = |input: &[u8]| {
        let mut out = Vec::with_capacity(input.len() / 100 + 1024);
        let before = c.total_in();
        while c.total_in() - before < input.len() as u64 || out.is_empty() {
            let done = (c.total_in() - before) as usize;
            out.reserve(4096);
            c.compress_vec(&input[done..], &mut out, FlushCompress::Sync)
                .unwrap();
        }
        out
    };
    let zeros = vec![0u8; RUN];
    let head = piece(&[prefix, &zeros].concat());
    let run = piece(&zeros);
    assert_eq!(
        run,
        piece(&zeros),
        "a run of zeros compresses the same way each time"
    );
    let runs = (INFLATED as usize - RUN) / RUN;
    let mut z = vec![0x78, 0xda];
    z.extend_from_slice(&head);
    for _ in 0..runs {
        z.extend_from_slice(&run);
    }
    // A final, empty stored block.
    z.extend_from_slice(&[0x01, 0x00, 0x00, 0xff, 0xff]);
    let total = (prefix.len() + RUN * (runs + 1)) as u64;
    let (mut a, mut b) = (1u64, 0u64);
    for &x in prefix {
        a = (a + u64::from(x)) % 65521;
        b = (b + a) % 65521;
    }
    // The zeros leave `a` as it is and add it to `b` once per byte.
    b = (b + a * ((total - prefix.len() as u64) % 65521)) % 65521;
    z.extend_from_slice(&((b << 16 | a) as u32).to_be_bytes());
    z
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut table = [0u32; 256];
    for (n, t) in table.iter_mut().enumerate() {
        let mut c = n as u32;
        for _ in 0..8 {
            c = if c & 1 != 0 {
                0xedb8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
        *t = c;
    }
    !bytes.iter().fold(!0u32, |c, &b| {
        table[((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8)
    })
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let start = out.len();
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32(&out[start..]);
    out.extend_from_slice(&crc.to_be_bytes());
}

/// A 1x1 8-bit grey PNG of value 77, with `extra` chunks before its image
/// data, whose IDAT is `idat` (or the pixel's own small stream).
fn grey_1x1(extra: &[(&[u8; 4], Vec<u8>)], idat: Option<Vec<u8>>) -> Vec<u8> {
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&1u32.to_be_bytes());
    ihdr.extend_from_slice(&1u32.to_be_bytes());
    ihdr.extend_from_slice(&[8, 0, 0, 0, 0]); // depth 8, grey, deflate, no filter, no interlace
    chunk(&mut png, b"IHDR", &ihdr);
    for (kind, data) in extra {
        chunk(&mut png, kind, data);
    }
    let idat = idat.unwrap_or_else(|| {
        use std::io::Write;
        let mut e = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
        e.write_all(&[0, 77]).unwrap(); // filter "none", the pixel
        e.finish().unwrap()
    });
    chunk(&mut png, b"IDAT", &idat);
    chunk(&mut png, b"IEND", &[]);
    png
}

fn status_kib(field: &str) -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status
        .lines()
        .find(|l| l.starts_with(field))
        .unwrap_or_else(|| panic!("no {field} in /proc/self/status"));
    line[field.len()..]
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .unwrap()
}

/// Runs `decode` and returns its result, the growth of the peak resident set
/// over the resident set before it (KiB) and the time it took.
fn measured<T>(decode: impl FnOnce() -> T) -> (T, u64, Duration) {
    // "5" resets the peak resident set to the current one (Linux 4.0).
    std::fs::write("/proc/self/clear_refs", "5").expect("cannot reset VmHWM");
    let before = status_kib("VmRSS:");
    let start = Instant::now();
    let result = decode();
    let took = start.elapsed();
    let growth = status_kib("VmHWM:").saturating_sub(before);
    (result, growth, took)
}

#[test]
fn png_bombs_decode_in_bounded_memory() {
    // The compressed payloads are the same stream of zeros; the chunks'
    // headers (keyword, flags) come before it.
    let stream = zlib_of_zeros(&[]);
    assert!(
        stream.len() < 4 << 20,
        "the bomb is {} bytes, not a few MiB",
        stream.len()
    );
    let iccp = [b"bomb\0\0".as_slice(), &stream].concat(); // name, method 0
    let ztxt = [b"Comment\0\0".as_slice(), &stream].concat(); // keyword, method 0
    let itxt = [b"Comment\0\x01\0\0\0".as_slice(), &stream].concat(); // compressed, method 0, no language or translation
    let bombs = [
        ("iCCP", grey_1x1(&[(b"iCCP", iccp)], None)),
        ("zTXt", grey_1x1(&[(b"zTXt", ztxt)], None)),
        ("iTXt", grey_1x1(&[(b"iTXt", itxt)], None)),
        // The pixel's filter byte and value, then a gigabyte more.
        ("IDAT", grey_1x1(&[], Some(zlib_of_zeros(&[0, 77])))),
    ];
    let mut report = Vec::new();
    for (what, png) in &bombs {
        let (image, growth, took) = measured(|| weft_front::texture_files::decode_png(png));
        let image = image.unwrap_or_else(|e| panic!("texture file with a bomb in {what}: {e}"));
        assert_eq!(
            (image.width, image.height, image.rgba8.as_slice()),
            (1, 1, [77, 77, 77, 255].as_slice()),
            "texture file with a bomb in {what}"
        );
        report.push(format!(
            "weft-front  {what}: +{growth} KiB peak, {took:.2?}"
        ));
        assert!(
            growth < MAX_GROWTH_KIB && took < Duration::from_secs(10),
            "texture file with a bomb in {what} ({} bytes inflating to {INFLATED}): \
             peak resident set +{growth} KiB (at most {MAX_GROWTH_KIB}), {took:.2?}",
            png.len()
        );

        let (image, growth, took) = measured(|| weft_render::decode_png(png, what));
        let image = image.unwrap_or_else(|e| panic!("--texture with a bomb in {what}: {e}"));
        assert_eq!(
            image,
            (1, 1, vec![77, 77, 77, 255]),
            "--texture with a bomb in {what}"
        );
        report.push(format!(
            "weft-render {what}: +{growth} KiB peak, {took:.2?}"
        ));
        assert!(
            growth < MAX_GROWTH_KIB && took < Duration::from_secs(10),
            "--texture with a bomb in {what} ({} bytes inflating to {INFLATED}): \
             peak resident set +{growth} KiB (at most {MAX_GROWTH_KIB}), {took:.2?}",
            png.len()
        );
    }
    println!("{}", report.join("\n"));
}
