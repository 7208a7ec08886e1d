// Run context: read from the system and the build, published into the JSON "context".
#include "run_context.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <fstream>

#include "pin.h"
#include "retro.h"

// The Makefile defines these for this object only, from the variables the kernels were
// compiled with, so the record describes the library rather than this C++ file.
#ifndef RETRO_BUILD_CC
#define RETRO_BUILD_CC "unknown"
#endif
#ifndef RETRO_BUILD_CFLAGS
#define RETRO_BUILD_CFLAGS "unknown"
#endif

static std::string cpuinfo_field(const std::string &key)
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.compare(0, key.size(), key) == 0 && line.find(':') != std::string::npos) {
            std::string v = line.substr(line.find(':') + 1);
            return v.erase(0, v.find_first_not_of(" \t"));
        }
    return "";
}

static std::string command_line(const char *cmd)
{
    std::string out;
    if (FILE *p = popen(cmd, "r")) {
        char buf[256];
        if (fgets(buf, sizeof buf, p))
            out = buf;
        pclose(p);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
        out.pop_back();
    return out;
}

void context_gather(RunContext *rc)
{
    rc->cpu_model = cpuinfo_field("model name");
    std::string family = cpuinfo_field("cpu family"), model = cpuinfo_field("model\t");
    if (rc->cpu_model.empty())
        rc->cpu_model = "unknown";
    // Virtual machines often hide the marketing name ("AMD EPYC"); family and model still
    // tell the microarchitecture apart.
    if (!family.empty())
        rc->cpu_model += " (family " + family + ", model " + model + ")";
    rc->cores = pin_core_count();
    rc->pus = pin_pu_count();
    rc->isa = retro_cpu_level_name(retro_cpu_features());
    retro_ctx *scratch = retro_ctx_new();
    rc->kernel_binding = scratch ? retro_ctx_binding(scratch) : "unknown (out of memory)";
    retro_ctx_free(scratch);
    rc->cc = RETRO_BUILD_CC;
    rc->cflags = RETRO_BUILD_CFLAGS;
#if defined(__clang__)
    rc->cxx = "clang++ " __clang_version__;
#elif defined(__GNUC__)
    rc->cxx = "g++ " __VERSION__;
#else
    rc->cxx = "unknown";
#endif
    rc->commit = command_line("git describe --always --dirty --abbrev=12 2>/dev/null");
    if (rc->commit.empty())
        rc->commit = "unknown (not a git checkout)";
    char date[64];
    std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    rc->date = date;
    std::ifstream("/proc/loadavg") >> rc->load;
    if (rc->load.empty())
        rc->load = "unknown";
}

void context_publish(const RunContext &rc)
{
    benchmark::AddCustomContext("retro_cpu_model", rc.cpu_model);
    benchmark::AddCustomContext("retro_cores", std::to_string(rc.cores));
    benchmark::AddCustomContext("retro_pus", std::to_string(rc.pus));
    benchmark::AddCustomContext("retro_binding", rc.binding);
    benchmark::AddCustomContext("retro_kernel_binding", rc.kernel_binding);
    benchmark::AddCustomContext("retro_isa", rc.isa);
    benchmark::AddCustomContext("retro_cc", rc.cc);
    benchmark::AddCustomContext("retro_cflags", rc.cflags);
    benchmark::AddCustomContext("retro_cxx", rc.cxx);
    benchmark::AddCustomContext("retro_commit", rc.commit);
    benchmark::AddCustomContext("retro_date", rc.date);
    benchmark::AddCustomContext("retro_load", rc.load);
    benchmark::AddCustomContext("retro_quick", rc.quick ? "true" : "false");
    benchmark::AddCustomContext("retro_machine", rc.machine);
}
