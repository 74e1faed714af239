// A dlopen'ed shared library, closed when the owner dies.
#pragma once

#include <dlfcn.h>

#include <string>

namespace m3055 {

class DynamicLibrary {
public:
    explicit DynamicLibrary(const std::string& name) : handle_(dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL)) {
        if (!handle_) {
            const char* error = dlerror();
            error_ = error ? error : ("cannot open " + name);
        }
    }
    ~DynamicLibrary() {
        if (handle_) dlclose(handle_);
    }
    DynamicLibrary(const DynamicLibrary&) = delete;
    DynamicLibrary& operator=(const DynamicLibrary&) = delete;

    bool ok() const { return handle_ != nullptr; }
    const std::string& error() const { return error_; }

    template <typename Fn>
    Fn symbol(const char* name) const {
        return handle_ ? reinterpret_cast<Fn>(dlsym(handle_, name)) : nullptr;
    }

private:
    void* handle_;
    std::string error_;
};

}  // namespace m3055
