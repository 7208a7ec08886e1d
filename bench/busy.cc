// Other work on the cores skews every timing (a 2-thread kernel came out slower than on one
// thread with another job running), so the run says so before it starts.
#include "busy.h"

#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

// Total and idle jiffies of the "cpu" line of /proc/stat.
static bool cpu_jiffies(unsigned long long *total, unsigned long long *idle)
{
    std::ifstream in("/proc/stat");
    std::string cpu;
    unsigned long long v[8] = {0};
    if (!(in >> cpu) || cpu != "cpu")
        return false;
    for (auto &x : v)
        in >> x;
    *total = 0;
    for (auto x : v)
        *total += x;
    *idle = v[3] + v[4]; // idle and iowait
    return static_cast<bool>(in);
}

struct Proc {
    std::string name;
    unsigned long long ticks;
};

// utime + stime of every process but this one.
static std::map<int, Proc> proc_ticks()
{
    std::map<int, Proc> out;
    const int self = static_cast<int>(getpid());
    DIR *d = opendir("/proc");
    if (!d)
        return out;
    while (dirent *e = readdir(d)) {
        int pid = std::atoi(e->d_name);
        if (pid <= 0 || pid == self)
            continue;
        std::ifstream in(std::string("/proc/") + e->d_name + "/stat");
        std::string line;
        if (!std::getline(in, line))
            continue;
        // The name is in parentheses and may hold spaces: fields resume after the last ')'.
        size_t open = line.find('('), close = line.rfind(')');
        if (open == std::string::npos || close == std::string::npos || close < open)
            continue;
        std::istringstream rest(line.substr(close + 2));
        std::string f;
        unsigned long long utime = 0, stime = 0;
        for (int i = 3; i <= 15 && rest >> f; i++) {
            if (i == 14)
                utime = std::strtoull(f.c_str(), nullptr, 10);
            if (i == 15)
                stime = std::strtoull(f.c_str(), nullptr, 10);
        }
        out[pid] = {line.substr(open + 1, close - open - 1), utime + stime};
    }
    closedir(d);
    return out;
}

BusyReport busy_sample(double seconds, int cores)
{
    BusyReport b;
    std::ifstream("/proc/loadavg") >> b.load1;
    unsigned long long t0, i0, t1, i1;
    bool ok = cpu_jiffies(&t0, &i0);
    std::map<int, Proc> p0 = proc_ticks();
    usleep(static_cast<useconds_t>(seconds * 1e6));
    ok = cpu_jiffies(&t1, &i1) && ok;
    std::map<int, Proc> p1 = proc_ticks();
    const double hz = static_cast<double>(sysconf(_SC_CLK_TCK));
    if (ok && t1 > t0) {
        long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
        double busy_frac = 1.0 - static_cast<double>(i1 - i0) / static_cast<double>(t1 - t0);
        b.busy_cores = busy_frac * static_cast<double>(ncpu > 0 ? ncpu : 1);
    }
    std::vector<std::pair<double, std::string>> users;
    for (const auto &[pid, p] : p1) {
        auto it = p0.find(pid);
        unsigned long long before = it == p0.end() ? 0 : it->second.ticks;
        if (it == p0.end() || p.ticks <= before)
            continue;
        double used = static_cast<double>(p.ticks - before) / hz / seconds;
        if (used >= 0.05)
            users.push_back({used, p.name + " (" + std::to_string(pid) + ")"});
    }
    std::sort(users.rbegin(), users.rend());
    for (size_t i = 0; i < users.size() && i < 3; i++) {
        char c[32];
        std::snprintf(c, sizeof c, " %.2f cores", users[i].first);
        b.top += (i ? ", " : "") + users[i].second + c;
    }
    // A tenth of a core taken by others, or more runnable work than cores, moves medians
    // by more than the differences the tables compare.
    b.busy = b.busy_cores > 0.1 || b.load1 > cores;
    return b;
}

std::string busy_sentence(const BusyReport &b)
{
    char s[160];
    std::snprintf(s, sizeof s, "%s: other work used %.2f cores over the second before the run; "
                  "load average %.2f", b.busy ? "busy" : "quiet", b.busy_cores, b.load1);
    std::string out = s;
    if (!b.top.empty())
        out += " (" + b.top + ")";
    return out;
}
