#pragma once
// The fuzz targets' files (issue 18): the tokens @dir, @fifo, @zero, @null, @empty and @scene in
// an argument stand for a directory, a FIFO, /dev/zero, /dev/null, an empty file and a valid
// scene file, all named *.json in a scratch folder made once per process; any other argument
// with a '/' is refused by substitute(), so that a fuzzer never reads or writes the machine's
// own files.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fuzzscratch {

struct Scratch {
    std::filesystem::path dir;
    Scratch() {
        char name[] = "/tmp/elastic-lab-fuzz-XXXXXX";
        if (!::mkdtemp(name)) std::abort();
        dir = name;
        std::filesystem::create_directory(dir / "dir.json");
        if (::mkfifo((dir / "fifo.json").c_str(), 0600) != 0) std::abort();
        std::filesystem::create_symlink("/dev/zero", dir / "zero.json");
        std::filesystem::create_symlink("/dev/null", dir / "null.json");
        std::ofstream(dir / "empty.json").flush();
        std::ofstream(dir / "scene.json") << R"({"format": "elastic-lab-scene", "version": 3, "scene": "ring2d",
            "integrator": "rk4", "parameters": {"ks": 100, "dt": 0.001}})";
    }
    ~Scratch() {
        std::error_code ignored;
        std::filesystem::remove_all(dir, ignored);
    }
};

inline const Scratch& scratch() {
    static const Scratch s;
    return s;
}

// Replaces the tokens; false when the argument names some other path.
inline bool substitute(std::string& arg) {
    static const char* tokens[] = {"dir", "fifo", "zero", "null", "empty", "scene"};
    for (const char* token : tokens) {
        const std::string at = std::string("@") + token;
        if (auto pos = arg.find(at); pos != std::string::npos) {
            arg.replace(pos, at.size(), (scratch().dir / (std::string(token) + ".json")).string());
            return true;
        }
    }
    return arg.find('/') == std::string::npos;
}

}  // namespace fuzzscratch
