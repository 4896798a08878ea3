// Fuzz target: the Python entry (issue 31). The interpreter is embedded with the module
// (python/elasticlab.cpp) compiled in as a built-in; the package's own Python (python/elasticlab/)
// is imported from the source tree around it, and fuzz/python_harness.py turns every input into
// a call of the package and checks what comes back (its docstring lists the properties). A
// finding is an exception out of the harness (an AssertionError, or anything it does not
// allow): printed, then abort(), which libFuzzer records as a crash.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <pybind11/embed.h>

namespace py = pybind11;

namespace {

py::object& harness() {
    static py::scoped_interpreter* interpreter = new py::scoped_interpreter();  // lives until exit
    static py::object fuzzOne = [] {
        py::module_ sys = py::module_::import("sys");
        sys.attr("path").attr("insert")(0, ELASTIC_LAB_SOURCE_DIR "/python");
        sys.attr("path").attr("insert")(0, ELASTIC_LAB_SOURCE_DIR "/fuzz");
        sys.attr("modules")["elasticlab._core"] = py::module_::import("_core");
        return py::module_::import("python_harness").attr("fuzz_one");
    }();
    (void)interpreter;
    return fuzzOne;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    py::object& fuzzOne = harness();
    try {
        fuzzOne(py::bytes(reinterpret_cast<const char*>(data), size));
    } catch (py::error_already_set& e) {
        std::fprintf(stderr, "fuzz_python: %s\n", e.what());
        std::abort();
    }
    return 0;
}
