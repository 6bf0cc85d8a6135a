// st_run: execute an IEC 61131-3 ST program on the ST compiler and virtual machine of
// pyplcopen's source distribution (core/st, header-only C++17, Apache-2.0), one scan per
// row of inputs. Built by `make st-engine` (Makefile); driven by analysis.plc.st_engine.
//
//   st_run SOURCE.st PROGRAM IN1,IN2,... OUT1,OUT2,...   < rows > results
//   st_run --key                                           (prints the build key)
//
// SOURCE.st holds every POU; PROGRAM names the one to load. Each row on stdin is one REAL
// (IEEE binary32, little-endian) per input. Before each scan the driver stores the row into
// the inputs: top-level VAR of PROGRAM, which live in the caller-owned variable buffer at the
// offsets the compiler reports (Instance::variable(i).offset), the way an HMI or a fieldbus
// writes a PLC's variables between two scans. Then one scan (Instance::scan), then each
// output is read with Instance::value_f64 (REAL, LREAL) or value_i64 (integers, BOOL) and
// written as one IEEE binary64 (little-endian) per output, followed by the scan's fault code
// (st::ScanError, 0 = ok; a faulted instance is reset before the next row, as a CPU restart).
// On exit the total time spent in scan() is written to stderr as "scan_ns <n> rows <m>".
// Compile diagnostics go to stderr as "line L col C: code: message", exit status 3. The code
// budget is 1 MiB of bytecode (CompileOptions::max_code_bytes; the engine's default, 64 KiB,
// is less than the PUMA 560's IK block and machine program take: capacity_code; jumps are u32).
#include "rt/error_text.h"
#include "st/st.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef ST_RUN_KEY
#define ST_RUN_KEY "unkeyed"
#endif

using namespace plcopen::core;

namespace {

std::vector<std::string> split(const std::string &s)
{
    std::vector<std::string> out;
    std::string cur;
    for(char c : s) {
        if(c == ',') { out.push_back(cur); cur.clear(); }
        else cur.push_back(c);
    }
    if(!cur.empty()) out.push_back(cur);
    return out;
}

bool is_real(st::Type t) { return t == st::Type::real || t == st::Type::lreal; }

} // namespace

int main(int argc, char **argv)
{
    if(argc == 2 && std::strcmp(argv[1], "--key") == 0) {
        std::printf("%s\n", ST_RUN_KEY);
        return 0;
    }
    if(argc != 5) {
        std::fprintf(stderr, "usage: st_run SOURCE.st PROGRAM IN1,IN2,... OUT1,OUT2,...\n");
        return 2;
    }
    std::ifstream file(argv[1], std::ios::binary);
    if(!file) { std::fprintf(stderr, "cannot read %s\n", argv[1]); return 2; }
    std::stringstream text;
    text << file.rdbuf();
    const std::string source = text.str();
    st::CompileOptions options;
    options.max_code_bytes = 1U << 20;  // the default 64 KiB: not a six-axis IK block and more
    const st::CompileResult compiled = st::compile(source, options);
    if(!compiled.ok) {
        for(const st::Diagnostic &d : compiled.diagnostics)
            std::fprintf(stderr, "line %d col %d: %s: %s\n", d.line, d.column,
                         st::to_string(d.code), d.message.c_str());
        return 3;
    }
    const std::string name = argv[2];
    const st::Program *program = &compiled.program;
    std::vector<std::uint64_t> storage((compiled.program.required_bytes() + 7U) / 8U + 1U);
    unsigned char *buffer = reinterpret_cast<unsigned char *>(storage.data());
    st::Instance vm;
    rt::ErrorCode loaded = vm.load(compiled.program, name.c_str(), buffer,
                                   storage.size() * sizeof(storage[0]), 1000000);
    if(loaded != rt::ErrorCode::ok) {
        std::fprintf(stderr, "load of program %s failed: %s\n", name.c_str(), rt::to_string(loaded));
        return 3;
    }
    (void)program;
    const std::vector<std::string> ins = split(argv[3]), outs = split(argv[4]);
    std::vector<std::uint32_t> in_offset;
    std::vector<int> out_index;
    for(const std::string &n : ins) {
        const int i = vm.find(n.c_str());
        if(i < 0 || vm.variable(i)->type != st::Type::real) {
            std::fprintf(stderr, "input %s is not a REAL variable of %s\n", n.c_str(), name.c_str());
            return 3;
        }
        in_offset.push_back(vm.variable(i)->offset);
    }
    for(const std::string &n : outs) {
        const int i = vm.find(n.c_str());
        if(i < 0) { std::fprintf(stderr, "output %s is not a variable of %s\n", n.c_str(), name.c_str()); return 3; }
        out_index.push_back(i);
    }
    std::vector<float> row(ins.size());
    std::vector<double> result(outs.size() + 1);
    std::int64_t scan_ns = 0, rows = 0;
    while(std::fread(row.data(), sizeof(float), row.size(), stdin) == row.size()) {
        for(std::size_t k = 0; k < row.size(); ++k)
            std::memcpy(buffer + in_offset[k], &row[k], sizeof(float));
        const auto t0 = std::chrono::steady_clock::now();
        const st::ScanError e = vm.scan(std::int64_t{1} << 40);
        scan_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::steady_clock::now() - t0).count();
        ++rows;
        for(std::size_t k = 0; k < out_index.size(); ++k) {
            const int i = out_index[k];
            result[k] = is_real(vm.variable(i)->type) ? vm.value_f64(i)
                                                      : static_cast<double>(vm.value_i64(i));
        }
        result[outs.size()] = static_cast<double>(static_cast<int>(e));
        std::fwrite(result.data(), sizeof(double), result.size(), stdout);
        if(e != st::ScanError::ok) vm.reset();
    }
    std::fprintf(stderr, "scan_ns %lld rows %lld\n", static_cast<long long>(scan_ns),
                 static_cast<long long>(rows));
    return 0;
}
