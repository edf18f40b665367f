// weft-d3d-compile: compiles many HLSL entry points in one process with the
// D3D-side compilers that only ship as Windows DLLs, and reflects their
// registers. Runs under wine; built with x86_64-w64-mingw32-g++ (see
// tools/d3d-compile/build.sh). Used by tests/hlsl_d3d.rs.
//
//   weft-d3d-compile.exe <dll-dir> <jobs-file> <results-file> [threads]
//
// <dll-dir> holds dxcompiler.dll + dxil.dll (DXC; older DXCs validate and
// sign DXIL with dxil.dll) and d3dcompiler_47.dll (FXC). Each line of <jobs-file> (UTF-8)
// is one entry point, fields separated by tabs:
//
//   <id> <tool> <hlsl-path> <entry> <profile> [<argument>...]
//
// <tool> is `dxc` (IDxcCompiler3::Compile with `-E <entry> -T <profile>` and
// the arguments, e.g. `-spirv` or `-HV` `2016`) or `fxc` (D3DCompile with no
// flags: FXC's defaults). Each line of <results-file> is one job:
//
//   <id> ok <resources> <warnings>
//   <id> error <messages>
//
// <resources> lists the reflected resource bindings, `;`-separated, each
// `name:register:space:count`, with register a letter (b, t, s, u) and a
// number: from ID3D12ShaderReflection::GetResourceBindingDesc (DXIL through
// IDxcUtils::CreateReflection; FXC's SM 5.1 bytecode through D3DReflect), or,
// for SPIR-V (`-spirv`), from the module's DescriptorSet/Binding decorations
// as `name:vk<binding>:<set>:1`. Text fields escape `\`, tab and newline as
// `\\`, `\t`, `\n`. The first line of <results-file> is a header:
//
//   # dxc <major>.<minor> dxil.dll <loaded|unused> fxc <loaded|missing>
//
// Every DXIL result must carry the validator's hash (a zero hash, from
// `-Vd` or a missing validator, is an error): DXC 1.9 validates with its
// internal validator, so dxil.dll is not loaded.

#include <windows.h>
#include <d3d12shader.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

// ---------------------------------------------------------------- DXC API
// The few dxcapi.h declarations used here (the MinGW headers have none), in
// the vtable order of DXC's published interface.

static const GUID kClsidDxcCompiler = {
    0x73e22d93, 0xe6ce, 0x47f3, {0xb5, 0xbf, 0xf0, 0x66, 0x4f, 0x39, 0xc1, 0xb0}};
static const GUID kClsidDxcUtils = {
    0x6245d6af, 0x66e0, 0x48fd, {0x80, 0xb4, 0x4d, 0x27, 0x17, 0x96, 0x74, 0x8c}};
static const GUID kIidDxcCompiler3 = {
    0x228b4687, 0x5a6a, 0x4730, {0x90, 0x0c, 0x97, 0x02, 0xb2, 0x20, 0x3f, 0x54}};
static const GUID kIidDxcUtils = {
    0x4605c4cb, 0x2019, 0x492a, {0xad, 0xa4, 0x65, 0xf2, 0x0b, 0xb7, 0xd6, 0x7f}};
static const GUID kIidDxcResult = {
    0x58346cda, 0xdde7, 0x4497, {0x94, 0x61, 0x6f, 0x87, 0xaf, 0x5e, 0x06, 0x59}};
static const GUID kIidDxcVersionInfo = {
    0xb04f5b50, 0x2059, 0x4f12, {0xa8, 0xff, 0xa1, 0xe0, 0xcd, 0xe1, 0xcc, 0x7e}};
static const GUID kIidD3D12ShaderReflection = {
    0x5a58797d, 0xa72c, 0x478d, {0x8b, 0xa2, 0xef, 0xc6, 0xb0, 0xef, 0xe8, 0x8e}};

struct DxcBuffer {
    const void *Ptr;
    SIZE_T Size;
    UINT Encoding;
};
static const UINT kCpUtf8 = 65001;

struct IDxcBlob : public IUnknown {
    virtual void *STDMETHODCALLTYPE GetBufferPointer() = 0;
    virtual SIZE_T STDMETHODCALLTYPE GetBufferSize() = 0;
};

struct IDxcBlobEncoding : public IDxcBlob {
    virtual HRESULT STDMETHODCALLTYPE GetEncoding(BOOL *known, UINT32 *code_page) = 0;
};

struct IDxcOperationResult : public IUnknown {
    virtual HRESULT STDMETHODCALLTYPE GetStatus(HRESULT *status) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetResult(IDxcBlob **result) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetErrorBuffer(IDxcBlobEncoding **errors) = 0;
};

// IDxcResult extends IDxcOperationResult; only the base methods are called.
struct IDxcResult : public IDxcOperationResult {};

struct IDxcCompiler3 : public IUnknown {
    virtual HRESULT STDMETHODCALLTYPE Compile(const DxcBuffer *source, LPCWSTR *arguments,
                                              UINT32 argument_count, IUnknown *include_handler,
                                              REFIID riid, void **result) = 0;
    virtual HRESULT STDMETHODCALLTYPE Disassemble(const DxcBuffer *object, REFIID riid,
                                                  void **result) = 0;
};

struct IDxcUtils : public IUnknown {
    virtual HRESULT STDMETHODCALLTYPE CreateBlobFromBlob(void *, UINT32, UINT32, void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE CreateBlobFromPinned(const void *, UINT32, UINT32,
                                                           void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE MoveToBlob(const void *, void *, UINT32, UINT32,
                                                 void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE CreateBlob(const void *, UINT32, UINT32, void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE LoadFile(LPCWSTR, UINT32 *, void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE CreateReadOnlyStreamFromBlob(void *, void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE CreateDefaultIncludeHandler(void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetBlobAsUtf8(void *, void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetBlobAsUtf16(void *, void **) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetDxilContainerPart(const DxcBuffer *, UINT32, void **,
                                                           UINT32 *) = 0;
    virtual HRESULT STDMETHODCALLTYPE CreateReflection(const DxcBuffer *data, REFIID iid,
                                                       void **reflection) = 0;
};

struct IDxcVersionInfo : public IUnknown {
    virtual HRESULT STDMETHODCALLTYPE GetVersion(UINT32 *major, UINT32 *minor) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetFlags(UINT32 *flags) = 0;
};

typedef HRESULT(WINAPI *DxcCreateInstanceFn)(REFCLSID, REFIID, void **);

// ---------------------------------------------------------------- FXC API

struct ID3DBlobLike : public IUnknown {
    virtual void *STDMETHODCALLTYPE GetBufferPointer() = 0;
    virtual SIZE_T STDMETHODCALLTYPE GetBufferSize() = 0;
};

typedef HRESULT(WINAPI *D3DCompileFn)(const void *, SIZE_T, const char *, const void *, void *,
                                      const char *, const char *, UINT, UINT, ID3DBlobLike **,
                                      ID3DBlobLike **);
typedef HRESULT(WINAPI *D3DReflectFn)(const void *, SIZE_T, REFIID, void **);

// GetProcAddress's FARPROC as the function type it is.
template <class F> static F proc(HMODULE module, const char *name) {
    FARPROC p = GetProcAddress(module, name);
    F f;
    static_assert(sizeof f == sizeof p, "function pointer sizes");
    memcpy(&f, &p, sizeof f);
    return f;
}

// ---------------------------------------------------------------- helpers

static DxcCreateInstanceFn g_dxc_create = nullptr;
static D3DCompileFn g_fxc_compile = nullptr;
static D3DReflectFn g_fxc_reflect = nullptr;

template <class T> static void release(T *&p) {
    if (p) {
        p->Release();
        p = nullptr;
    }
}

static std::wstring widen(const std::string &s) {
    if (s.empty()) return std::wstring();
    int n = MultiByteToWideChar(CP_UTF8, 0, s.data(), (int)s.size(), nullptr, 0);
    std::wstring w(n, L'\0');
    MultiByteToWideChar(CP_UTF8, 0, s.data(), (int)s.size(), &w[0], n);
    return w;
}

static std::string escape(const std::string &s) {
    std::string out;
    for (char c : s) {
        if (c == '\\') out += "\\\\";
        else if (c == '\t') out += "\\t";
        else if (c == '\n') out += "\\n";
        else if (c == '\r') continue;
        else out += c;
    }
    return out;
}

static std::vector<std::string> split(const std::string &line, char sep) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (;;) {
        size_t end = line.find(sep, start);
        parts.push_back(line.substr(start, end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return parts;
}

static bool read_file(const std::string &path, std::string &out) {
    FILE *f = _wfopen(widen(path).c_str(), L"rb");
    if (!f) return false;
    char buf[65536];
    size_t n;
    out.clear();
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
    fclose(f);
    return true;
}

static char register_letter(D3D_SHADER_INPUT_TYPE type) {
    switch (type) {
    case D3D_SIT_CBUFFER: return 'b';
    case D3D_SIT_TBUFFER:
    case D3D_SIT_TEXTURE:
    case D3D_SIT_STRUCTURED:
    case D3D_SIT_BYTEADDRESS: return 't';
    case D3D_SIT_SAMPLER: return 's';
    default: return 'u';
    }
}

static std::string reflect_d3d12(ID3D12ShaderReflection *r) {
    D3D12_SHADER_DESC desc;
    if (FAILED(r->GetDesc(&desc))) return "?";
    std::string out;
    for (UINT i = 0; i < desc.BoundResources; i++) {
        D3D12_SHADER_INPUT_BIND_DESC b;
        if (FAILED(r->GetResourceBindingDesc(i, &b))) continue;
        char item[512];
        snprintf(item, sizeof item, "%s%s:%c%u:%u:%u", out.empty() ? "" : ";", b.Name,
                 register_letter(b.Type), b.BindPoint, b.Space, b.BindCount);
        out += item;
    }
    return out;
}

// DescriptorSet/Binding decorations of a SPIR-V module, named by OpName.
static std::string reflect_spirv(const uint32_t *words, size_t count) {
    if (count < 5 || words[0] != 0x07230203) return "?";
    struct Var {
        uint32_t id;
        std::string name;
        int64_t set = -1, binding = -1;
    };
    std::vector<Var> vars;
    auto var = [&](uint32_t id) -> Var & {
        for (auto &v : vars)
            if (v.id == id) return v;
        vars.push_back(Var{id, std::string()});
        return vars.back();
    };
    std::vector<std::pair<uint32_t, std::string>> names;
    for (size_t i = 5; i < count;) {
        uint32_t op = words[i] & 0xffff, len = words[i] >> 16;
        if (len == 0 || i + len > count) return "?";
        if (op == 5 && len >= 3) { // OpName
            const char *s = reinterpret_cast<const char *>(&words[i + 2]);
            names.emplace_back(words[i + 1], std::string(s, strnlen(s, (len - 2) * 4)));
        } else if (op == 71 && len >= 4) { // OpDecorate
            if (words[i + 2] == 34) var(words[i + 1]).set = words[i + 3];
            if (words[i + 2] == 33) var(words[i + 1]).binding = words[i + 3];
        }
        i += len;
    }
    std::string out;
    for (auto &v : vars) {
        if (v.set < 0 || v.binding < 0) continue;
        for (auto &n : names)
            if (n.first == v.id) v.name = n.second;
        char item[512];
        snprintf(item, sizeof item, "%s%s:vk%lld:%lld:1", out.empty() ? "" : ";", v.name.c_str(),
                 (long long)v.binding, (long long)v.set);
        out += item;
    }
    return out;
}

struct Job {
    std::string id, tool, path, entry, profile;
    std::vector<std::string> args;
    std::string result;
};

struct Worker {
    IDxcCompiler3 *compiler = nullptr;
    IDxcUtils *utils = nullptr;
};

static std::string blob_text(IUnknown *blob) {
    if (!blob) return std::string();
    IDxcBlob *b = static_cast<IDxcBlob *>(blob);
    const char *p = static_cast<const char *>(b->GetBufferPointer());
    size_t n = b->GetBufferSize();
    while (n > 0 && p[n - 1] == '\0') n--;
    return std::string(p, n);
}

static std::string run_dxc(Worker &w, const Job &job, const std::string &source) {
    if (!w.compiler) return "error\tdxcompiler.dll not loaded";
    std::vector<std::wstring> wargs;
    wargs.push_back(widen(job.path));
    wargs.push_back(L"-E");
    wargs.push_back(widen(job.entry));
    wargs.push_back(L"-T");
    wargs.push_back(widen(job.profile));
    bool spirv = false;
    for (auto &a : job.args) {
        if (a == "-spirv") spirv = true;
        wargs.push_back(widen(a));
    }
    std::vector<LPCWSTR> argv;
    for (auto &a : wargs) argv.push_back(a.c_str());
    DxcBuffer buf = {source.data(), source.size(), kCpUtf8};
    IDxcResult *result = nullptr;
    HRESULT hr = w.compiler->Compile(&buf, argv.data(), (UINT32)argv.size(), nullptr,
                                     kIidDxcResult, reinterpret_cast<void **>(&result));
    if (FAILED(hr) || !result) {
        char msg[64];
        snprintf(msg, sizeof msg, "error\tCompile returned 0x%08lx", (unsigned long)hr);
        return msg;
    }
    HRESULT status = E_FAIL;
    result->GetStatus(&status);
    IDxcBlobEncoding *errors = nullptr;
    result->GetErrorBuffer(&errors);
    std::string messages = blob_text(errors);
    release(errors);
    if (FAILED(status)) {
        release(result);
        return "error\t" + escape(messages.empty() ? "compilation failed" : messages);
    }
    IDxcBlob *object = nullptr;
    result->GetResult(&object);
    release(result);
    if (!object) return "error\tno object";
    std::string resources;
    DxcBuffer obj = {object->GetBufferPointer(), object->GetBufferSize(), 0};
    if (spirv) {
        resources = reflect_spirv(static_cast<const uint32_t *>(obj.Ptr), obj.Size / 4);
    } else {
        // A DXIL container's bytes 4..20 are the validator's hash; all zero
        // means no validator ran (an unsigned container D3D12 refuses).
        const unsigned char *bytes = static_cast<const unsigned char *>(obj.Ptr);
        bool hashed = false;
        for (size_t i = 4; i < 20 && i < obj.Size; i++) hashed = hashed || bytes[i] != 0;
        if (!hashed) {
            release(object);
            return "error\tDXIL container not validated (zero hash)\t" + escape(messages);
        }
        ID3D12ShaderReflection *r = nullptr;
        if (SUCCEEDED(w.utils->CreateReflection(&obj, kIidD3D12ShaderReflection,
                                                reinterpret_cast<void **>(&r))) &&
            r) {
            resources = reflect_d3d12(r);
            release(r);
        } else {
            resources = "?";
        }
    }
    release(object);
    return "ok\t" + resources + "\t" + escape(messages);
}

static std::string run_fxc(const Job &job, const std::string &source) {
    if (!g_fxc_compile) return "error\td3dcompiler_47.dll not loaded";
    ID3DBlobLike *code = nullptr, *errors = nullptr;
    HRESULT hr = g_fxc_compile(source.data(), source.size(), job.path.c_str(), nullptr, nullptr,
                               job.entry.c_str(), job.profile.c_str(), 0, 0, &code, &errors);
    std::string messages = blob_text(errors);
    release(errors);
    if (FAILED(hr) || !code) {
        release(code);
        return "error\t" + escape(messages.empty() ? "compilation failed" : messages);
    }
    std::string resources = "?";
    ID3D12ShaderReflection *r = nullptr;
    if (SUCCEEDED(g_fxc_reflect(code->GetBufferPointer(), code->GetBufferSize(),
                                kIidD3D12ShaderReflection, reinterpret_cast<void **>(&r))) &&
        r) {
        resources = reflect_d3d12(r);
        release(r);
    }
    release(code);
    return "ok\t" + resources + "\t" + escape(messages);
}

static std::vector<Job> g_jobs;
static volatile LONG g_next = 0;

static DWORD WINAPI worker_main(void *) {
    Worker w;
    if (g_dxc_create) {
        g_dxc_create(kClsidDxcCompiler, kIidDxcCompiler3, reinterpret_cast<void **>(&w.compiler));
        g_dxc_create(kClsidDxcUtils, kIidDxcUtils, reinterpret_cast<void **>(&w.utils));
    }
    std::string path, source;
    for (;;) {
        LONG i = InterlockedIncrement(&g_next) - 1;
        if (i >= (LONG)g_jobs.size()) break;
        Job &job = g_jobs[i];
        if (job.path != path) {
            path = job.path;
            if (!read_file(path, source)) {
                source.clear();
                job.result = "error\tcannot read " + escape(path);
                path.clear();
                continue;
            }
        }
        if (job.tool == "dxc") job.result = run_dxc(w, job, source);
        else if (job.tool == "fxc") job.result = run_fxc(job, source);
        else job.result = "error\tunknown tool " + escape(job.tool);
    }
    release(w.utils);
    release(w.compiler);
    return 0;
}

int main(int argc, char **argv) {
    if (argc < 4) {
        fprintf(stderr, "usage: %s <dll-dir> <jobs-file> <results-file> [threads]\n", argv[0]);
        return 2;
    }
    std::wstring dlls = widen(argv[1]);
    // dxcompiler.dll loads dxil.dll by name: let it find it in <dll-dir>.
    SetDllDirectoryW(dlls.c_str());
    HMODULE dxc = LoadLibraryW((dlls + L"\\dxcompiler.dll").c_str());
    if (dxc) g_dxc_create = proc<DxcCreateInstanceFn>(dxc, "DxcCreateInstance");
    HMODULE fxc = LoadLibraryW((dlls + L"\\d3dcompiler_47.dll").c_str());
    if (fxc) {
        g_fxc_compile = proc<D3DCompileFn>(fxc, "D3DCompile");
        g_fxc_reflect = proc<D3DReflectFn>(fxc, "D3DReflect");
    }
    UINT32 major = 0, minor = 0;
    if (g_dxc_create) {
        IDxcVersionInfo *v = nullptr;
        IUnknown *c = nullptr;
        if (SUCCEEDED(g_dxc_create(kClsidDxcCompiler, kIidDxcCompiler3,
                                   reinterpret_cast<void **>(&c))) &&
            c) {
            if (SUCCEEDED(c->QueryInterface(kIidDxcVersionInfo, reinterpret_cast<void **>(&v))) &&
                v) {
                v->GetVersion(&major, &minor);
                release(v);
            }
            release(c);
        }
    }

    std::string list;
    if (!read_file(argv[2], list)) {
        fprintf(stderr, "cannot read %s\n", argv[2]);
        return 2;
    }
    for (auto &line : split(list, '\n')) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        auto f = split(line, '\t');
        if (f.size() < 5) {
            fprintf(stderr, "bad job line: %s\n", line.c_str());
            return 2;
        }
        Job job{f[0], f[1], f[2], f[3], f[4], {}, {}};
        job.args.assign(f.begin() + 5, f.end());
        g_jobs.push_back(job);
    }

    int threads = argc > 4 ? atoi(argv[4]) : 0;
    if (threads <= 0) {
        SYSTEM_INFO si;
        GetSystemInfo(&si);
        threads = (int)si.dwNumberOfProcessors;
    }
    std::vector<HANDLE> handles;
    for (int t = 0; t < threads; t++) {
        HANDLE h = CreateThread(nullptr, 64 << 20, worker_main, nullptr, 0, nullptr);
        if (h) handles.push_back(h);
    }
    for (HANDLE h : handles) {
        WaitForSingleObject(h, INFINITE);
        CloseHandle(h);
    }

    FILE *out = _wfopen(widen(argv[3]).c_str(), L"wb");
    if (!out) {
        fprintf(stderr, "cannot write %s\n", argv[3]);
        return 2;
    }
    // DXC 1.9 validates and hashes with its internal validator; older
    // versions load dxil.dll for that.
    fprintf(out, "# dxc %u.%u dxil.dll %s fxc %s\n", major, minor,
            GetModuleHandleW(L"dxil.dll") ? "loaded" : "unused",
            g_fxc_compile && g_fxc_reflect ? "loaded" : "missing");
    for (auto &job : g_jobs) fprintf(out, "%s\t%s\n", job.id.c_str(), job.result.c_str());
    fclose(out);
    return 0;
}
