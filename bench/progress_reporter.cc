// Progress and collection: google-benchmark reports a case only after its last repetition,
// so a line here means the case is done and its median final.
#include "progress_reporter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "bench_report.h"

static const char *const kMsCounter = "ms/frame";

ProgressReporter::ProgressReporter(BenchPlan *plan) : plan_(plan), start_(std::chrono::steady_clock::now())
{
    for (auto &c : plan->cases)
        by_name_[c->name] = c.get();
}

double ProgressReporter::seconds() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

// Every pass over the cases starts with a context; the run's clock starts at the first.
bool ProgressReporter::ReportContext(const Context &)
{
    if (!started_)
        start_ = std::chrono::steady_clock::now();
    started_ = true;
    return true;
}

static double counter(const benchmark::BenchmarkReporter::Run &r, const char *name)
{
    auto it = r.counters.find(name);
    return it == r.counters.end() ? NAN : it->second.value;
}

void ProgressReporter::ReportRuns(const std::vector<Run> &runs)
{
    if (runs.empty())
        return;
    // function_name is the name we registered; the full name carries suffixes such as
    // "/real_time" that the case table does not know about.
    auto it = by_name_.find(runs.front().run_name.function_name);
    if (it == by_name_.end())
        return;
    BenchCase *c = it->second;
    std::vector<Run> kept = runs;
    for (Run &r : kept) // they point into the pass's benchmark instances, gone after it
        r.statistics = nullptr;
    runs_[c].push_back(std::move(kept));
    // A case arrives in two calls, its repetitions then their aggregates; the second call
    // is skipped when there are no aggregates (one repetition, or every one failed) and,
    // with --benchmark_display_aggregates_only, the first is.
    bool last = false;
    std::vector<double> each;
    std::map<std::string, std::vector<double>> probes;
    const char *ms = c->frame_median ? FRAME_MEDIAN_COUNTER : kMsCounter;
    for (const Run &r : runs) {
        if (r.error_occurred) {
            c->error = r.error_message;
            last = true;
        } else if (r.run_type == Run::RT_Aggregate) {
            if (r.aggregate_name == "median")
                c->median_ms = counter(r, ms);
            else if (r.aggregate_name == "cv")
                c->cv = counter(r, ms);
            last = true;
        } else {
            each.push_back(counter(r, ms));
            for (const auto &[name, value] : r.counters)
                if (name.find(PROBE_COUNTER) != std::string::npos)
                    probes[name].push_back(value.value);
            last |= r.repetitions <= 1;
        }
    }
    // Our own median until (unless) the aggregate arrives.
    if (!each.empty()) {
        std::sort(each.begin(), each.end());
        c->median_ms = sorted_median(each);
        c->reps = static_cast<int>(each.size());
        c->rep_min = each.front();
        c->rep_max = each.back();
    }
    for (auto &[name, v] : probes) {
        std::sort(v.begin(), v.end());
        c->probes[name] = sorted_median(v);
    }
    if (!last)
        return;
    c->ran = true;
    c->done_at = seconds();
    done_++;
    if (!c->error.empty())
        std::fprintf(stderr, "[%3d] %6.1fs  %-46s skipped: %s\n", done_, seconds(),
                     c->name.c_str(), c->error.c_str());
    else if (std::isnan(c->cv))
        std::fprintf(stderr, "[%3d] %6.1fs  %-46s %9.3f ms/frame\n", done_, seconds(),
                     c->name.c_str(), c->median_ms);
    else
        std::fprintf(stderr, "[%3d] %6.1fs  %-46s %9.3f ms/frame  cv %4.1f%%\n", done_,
                     seconds(), c->name.c_str(), c->median_ms, 100 * c->cv);
}

bool ProgressReporter::write_json(const std::string &path) const
{
    std::ostringstream text, errors;
    benchmark::JSONReporter json;
    json.SetOutputStream(&text);
    json.SetErrorStream(&errors);
    json.ReportContext(Context());
    for (const auto &c : plan_->cases) {
        auto it = runs_.find(c.get());
        if (it != runs_.end())
            for (const auto &batch : it->second)
                json.ReportRuns(batch);
    }
    json.Finalize();
    if (!errors.str().empty())
        std::fprintf(stderr, "%s", errors.str().c_str());
    return report_write_file(path, text.str());
}
