//! HTTP/1.1 on one connection, within bounds: a request head is read into
//! a buffer no larger than the request-line and header caps allow, under a
//! deadline for the whole head (a client sending a byte at a time cannot
//! hold the connection longer) and an idle deadline between kept-alive
//! requests. Bodies are never read: the server only answers GET and HEAD,
//! and a request announcing a body is answered and its connection closed.

use std::io::{self, Read, Write};
use std::net::{Shutdown, TcpStream};
use std::time::{Duration, Instant};

/// What one client may cost `weft serve`.
#[derive(Clone, Debug)]
pub struct Limits {
    /// Longest request line (method, target, version, line end), in bytes;
    /// longer: 414.
    pub max_request_line: usize,
    /// Most bytes of header fields after the request line (the blank line
    /// ending them included); more: 431.
    pub max_headers: usize,
    /// How long a request head may take to arrive: from the connection, or
    /// from its first byte on a kept-alive connection. Later: 408, closed.
    pub header_timeout: Duration,
    /// How long a kept-alive connection may wait for its next request
    /// before it is closed.
    pub idle_timeout: Duration,
    /// How long one write may block on a client that does not read.
    pub write_timeout: Duration,
    /// Most connections served at once (each has a thread); more are
    /// answered 503 and closed.
    pub max_connections: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            max_request_line: 8 * 1024,
            max_headers: 64 * 1024,
            header_timeout: Duration::from_secs(10),
            idle_timeout: Duration::from_secs(5),
            write_timeout: Duration::from_secs(10),
            max_connections: 128,
        }
    }
}

/// A request head.
#[derive(Debug)]
pub struct Request {
    pub method: String,
    /// The request target as sent (`/path?query`).
    pub target: String,
    /// Every `Host` header's value.
    pub hosts: Vec<String>,
    /// The client keeps the connection for another request.
    pub keep_alive: bool,
    /// A body follows (`Content-Length` not 0, or `Transfer-Encoding`): the
    /// connection cannot carry another request, since the body is not read.
    pub has_body: bool,
}

/// What reading the next request head gave.
#[derive(Debug)]
pub enum Head {
    Request(Request),
    /// The client closed, or stayed idle before starting a request: close
    /// without an answer.
    Closed,
    /// Answer with this status and message, then close.
    Refuse(u16, &'static str),
}

/// One client connection and the bytes received but not yet used (the
/// start of a pipelined request).
pub struct Conn {
    pub stream: TcpStream,
    buf: Vec<u8>,
    limits: Limits,
}

impl Conn {
    pub fn new(stream: TcpStream, limits: Limits) -> Conn {
        let _ = stream.set_write_timeout(Some(limits.write_timeout));
        let _ = stream.set_nodelay(true);
        Conn {
            stream,
            buf: Vec::new(),
            limits,
        }
    }

    /// Reads the next request head. `first`: the connection's first request
    /// (its wait is the header timeout, a later one's the idle timeout).
    pub fn next_request(&mut self, first: bool) -> Head {
        let l = &self.limits;
        let mut deadline = Instant::now()
            + if first {
                l.header_timeout
            } else {
                l.idle_timeout
            };
        let mut started = first || !self.buf.is_empty();
        if started && !first {
            deadline = Instant::now() + l.header_timeout;
        }
        let mut parser = HeadParser::default();
        let mut chunk = [0u8; 8192];
        loop {
            match parser.advance(&self.buf, l) {
                Ok(Some((request, end))) => {
                    self.buf.drain(..end);
                    return Head::Request(request);
                }
                Ok(None) => {}
                Err((code, why)) => return Head::Refuse(code, why),
            }
            let now = Instant::now();
            if now >= deadline {
                return if started && !self.buf.is_empty() {
                    Head::Refuse(408, "the request head did not arrive in time")
                } else {
                    Head::Closed
                };
            }
            let _ = self.stream.set_read_timeout(Some(deadline - now));
            match self.stream.read(&mut chunk) {
                Ok(0) => return Head::Closed,
                Ok(n) => {
                    if !started {
                        // An idle kept-alive connection starts a request:
                        // its head gets the header timeout from now.
                        started = true;
                        deadline = Instant::now() + l.header_timeout;
                    }
                    self.buf.extend_from_slice(&chunk[..n]);
                }
                Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
                    ) => {}
                Err(_) => return Head::Closed,
            }
        }
    }

    /// Answers `status` with `body`; `head_only` (HEAD) leaves the body
    /// out, `close` tells the client the connection ends.
    pub fn respond(
        &mut self,
        status: u16,
        headers: &[(&str, &str)],
        body: &[u8],
        head_only: bool,
        close: bool,
    ) -> io::Result<()> {
        let mut head = format!("HTTP/1.1 {status} {}\r\n", reason(status));
        for (k, v) in headers {
            head.push_str(&format!("{k}: {v}\r\n"));
        }
        head.push_str(&format!("Content-Length: {}\r\n", body.len()));
        if close {
            head.push_str("Connection: close\r\n");
        }
        head.push_str("\r\n");
        let mut out = head.into_bytes();
        if !head_only {
            out.extend_from_slice(body);
        }
        self.stream.write_all(&out)?;
        self.stream.flush()
    }

    /// A plain-text answer.
    pub fn respond_text(&mut self, status: u16, text: &str, head_only: bool, close: bool) {
        let ct = [("Content-Type", "text/plain; charset=utf-8")];
        let _ = self.respond(status, &ct, text.as_bytes(), head_only, close);
    }

    /// Answers and closes without blocking on the client: what it has sent
    /// already is read and dropped (unread data would turn the close into
    /// a reset that can discard the answer), nothing more is waited for.
    pub fn refuse_at_once(mut self, status: u16, text: &str) {
        self.respond_text(status, text, false, true);
        let _ = self.stream.shutdown(Shutdown::Write);
        if self.stream.set_nonblocking(true).is_ok() {
            let mut chunk = [0u8; 4096];
            for _ in 0..16 {
                if !matches!(self.stream.read(&mut chunk), Ok(n) if n > 0) {
                    break;
                }
            }
        }
    }

    /// Closes after an answer the client may still be sending to (a refused
    /// head, a body never read): ends the write side, then reads and drops
    /// what arrives for a bounded time and amount, so the answer is not
    /// lost to a reset caused by unread data.
    pub fn linger_close(self) {
        let _ = self.stream.shutdown(Shutdown::Write);
        let deadline = Instant::now() + LINGER_TIME;
        let mut drained = 0usize;
        let mut chunk = [0u8; 16384];
        let mut stream = &self.stream;
        while drained < LINGER_BYTES {
            let now = Instant::now();
            if now >= deadline {
                break;
            }
            let _ = stream.set_read_timeout(Some(deadline - now));
            match stream.read(&mut chunk) {
                Ok(0) => break,
                Ok(n) => drained += n,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                Err(_) => break,
            }
        }
    }
}

/// How long and how much [`Conn::linger_close`] drains.
const LINGER_TIME: Duration = Duration::from_secs(2);
const LINGER_BYTES: usize = 16 << 20;

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        414 => "URI Too Long",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        503 => "Service Unavailable",
        _ => "",
    }
}

/// Parses a head line by line as its bytes arrive (each byte is looked at
/// once, however slowly it comes).
#[derive(Default)]
struct HeadParser {
    /// Start of the first line not parsed yet.
    pos: usize,
    /// Where the header fields begin, once the request line is parsed.
    fields_start: Option<usize>,
    request: Option<Request>,
}

type Refusal = (u16, &'static str);

impl HeadParser {
    /// Parses the complete lines of `buf` not seen yet: the request and
    /// where its head ends, None while incomplete, or why it is refused.
    fn advance(&mut self, buf: &[u8], l: &Limits) -> Result<Option<(Request, usize)>, Refusal> {
        const LONG_LINE: Refusal = (414, "request line too long");
        const BIG_HEAD: Refusal = (431, "request header fields too large");
        while let Some(nl) = buf[self.pos..].iter().position(|&b| b == b'\n') {
            let end = self.pos + nl + 1;
            let line = &buf[self.pos..self.pos + nl];
            let line = line.strip_suffix(b"\r").unwrap_or(line);
            self.pos = end;
            match self.fields_start {
                None => {
                    // Blank lines before a request line are allowed (RFC
                    // 9112 2.2); they count towards its length.
                    if end > l.max_request_line {
                        return Err(LONG_LINE);
                    }
                    if !line.is_empty() {
                        self.request = Some(request_line(line)?);
                        self.fields_start = Some(end);
                    }
                }
                Some(start) => {
                    if end - start > l.max_headers {
                        return Err(BIG_HEAD);
                    }
                    const LOST: Refusal = (500, "request line lost");
                    if line.is_empty() {
                        let mut request = self.request.take().ok_or(LOST)?;
                        request.keep_alive &= !request.has_body;
                        return Ok(Some((request, end)));
                    }
                    header_line(line, self.request.as_mut().ok_or(LOST)?)?;
                }
            }
        }
        // The line being received.
        match self.fields_start {
            None if buf.len() > l.max_request_line => Err(LONG_LINE),
            Some(start) if buf.len() - start > l.max_headers => Err(BIG_HEAD),
            _ => Ok(None),
        }
    }
}

fn is_token(s: &[u8]) -> bool {
    !s.is_empty()
        && s.iter()
            .all(|&b| b.is_ascii_alphanumeric() || b"!#$%&'*+-.^_`|~".contains(&b))
}

/// `METHOD SP target SP HTTP/1.x`.
fn request_line(line: &[u8]) -> Result<Request, Refusal> {
    const BAD: Refusal = (400, "malformed request line");
    let text = std::str::from_utf8(line).map_err(|_| BAD)?;
    let mut parts = text.split(' ');
    let (Some(method), Some(target), Some(version), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(BAD);
    };
    if !is_token(method.as_bytes())
        || target.is_empty()
        || target.bytes().any(|b| b.is_ascii_control())
    {
        return Err(BAD);
    }
    let keep_alive = match version {
        "HTTP/1.1" => true,
        "HTTP/1.0" => false,
        _ => return Err((400, "not an HTTP/1.0 or HTTP/1.1 request")),
    };
    Ok(Request {
        method: method.to_string(),
        target: target.to_string(),
        hosts: Vec::new(),
        keep_alive,
        has_body: false,
    })
}

/// `name: value`; only the fields the server acts on are kept.
fn header_line(line: &[u8], request: &mut Request) -> Result<(), Refusal> {
    const BAD: Refusal = (400, "malformed header field");
    let colon = line.iter().position(|&b| b == b':').ok_or(BAD)?;
    let (name, value) = (&line[..colon], &line[colon + 1..]);
    // A name with white space or a folded line (starting with white space)
    // is refused: servers disagreeing on them is how requests are smuggled.
    if !is_token(name) || value.contains(&0) {
        return Err(BAD);
    }
    let value = String::from_utf8_lossy(value);
    let value = value.trim_matches([' ', '\t']);
    let name = String::from_utf8_lossy(name).to_ascii_lowercase();
    match name.as_str() {
        "host" => request.hosts.push(value.to_string()),
        "connection" => {
            for token in value.split(',').map(|t| t.trim().to_ascii_lowercase()) {
                match token.as_str() {
                    "close" => request.keep_alive = false,
                    "keep-alive" => request.keep_alive = true,
                    _ => {}
                }
            }
        }
        "content-length" => {
            let n: u64 = value
                .parse()
                .map_err(|_| (400, "malformed Content-Length"))?;
            request.has_body |= n > 0;
        }
        "transfer-encoding" => request.has_body = true,
        _ => {}
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(bytes: &[u8]) -> Result<Option<(Request, usize)>, Refusal> {
        HeadParser::default().advance(bytes, &Limits::default())
    }

    #[test]
    fn parses_heads_and_refuses_malformed_ones() {
        let pipelined = b"\r\nGET /a?b HTTP/1.1\r\nHost: x\r\nHOST:y \r\n\r\nGET";
        let (r, end) = parse(pipelined).unwrap().unwrap();
        assert_eq!((r.method.as_str(), r.target.as_str()), ("GET", "/a?b"));
        assert_eq!(r.hosts, ["x", "y"]);
        assert!(r.keep_alive && !r.has_body);
        assert_eq!(&pipelined[end..], b"GET", "the next request stays");
        let r = parse(b"GET / HTTP/1.0\nContent-Length: 3\n\n")
            .unwrap()
            .unwrap()
            .0;
        assert!(!r.keep_alive && r.has_body);
        assert!(parse(b"GET / HTTP/1.1\r\nHost: x\r\n").unwrap().is_none());
        for bad in [
            &b"GET /\r\n\r\n"[..],
            b"GET  / HTTP/1.1\r\n\r\n",
            b"GET / HTTP/2\r\n\r\n",
            b"G(T / HTTP/1.1\r\n\r\n",
            b"GET / HTTP/1.1\r\nHost : x\r\n\r\n",
            b"GET / HTTP/1.1\r\nA: b\r\n folded\r\n\r\n",
            b"GET / HTTP/1.1\r\nContent-Length: -1\r\n\r\n",
            b"\x00\xff\r\n\r\n",
        ] {
            assert_eq!(parse(bad).err().map(|e| e.0), Some(400), "{bad:?}");
        }
    }

    #[test]
    fn caps_the_request_line_and_the_header_fields() {
        let l = Limits::default();
        let line = format!("GET /{} HTTP/1.1\r\n", "a".repeat(l.max_request_line));
        assert_eq!(parse(line.as_bytes()).err().map(|e| e.0), Some(414));
        // Refused before the line ends.
        let partial = vec![b'a'; l.max_request_line + 1];
        assert_eq!(parse(&partial).err().map(|e| e.0), Some(414));
        let big = format!("GET / HTTP/1.1\r\nX: {}", "a".repeat(l.max_headers));
        assert_eq!(parse(big.as_bytes()).err().map(|e| e.0), Some(431));
        let many = format!(
            "GET / HTTP/1.1\r\n{}\r\n",
            "X: a\r\n".repeat(l.max_headers / 6 + 1)
        );
        assert_eq!(parse(many.as_bytes()).err().map(|e| e.0), Some(431));
        // Just inside the caps: parsed.
        let fits = format!(
            "GET /{} HTTP/1.1\r\n{}\r\n",
            "a".repeat(l.max_request_line - 16),
            "X: a\r\n".repeat(l.max_headers / 6 - 1)
        );
        assert!(parse(fits.as_bytes()).unwrap().is_some());
    }
}
