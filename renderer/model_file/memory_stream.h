// An std::istream over bytes already in memory, without copying them (a
// model file of 100 MB is not held twice while tinyobjloader reads it).
#pragma once

#include <istream>
#include <streambuf>
#include <string>

namespace m3055::model_file {

class MemoryBuffer : public std::streambuf {
public:
    explicit MemoryBuffer(const std::string& bytes) {
        char* begin = const_cast<char*>(bytes.data());  // only read: the get area
        setg(begin, begin, begin + bytes.size());
    }
};

class MemoryStream : public std::istream {
public:
    explicit MemoryStream(const std::string& bytes) : std::istream(nullptr), buffer_(bytes) { rdbuf(&buffer_); }

private:
    MemoryBuffer buffer_;
};

}  // namespace m3055::model_file
