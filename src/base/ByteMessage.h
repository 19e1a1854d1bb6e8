// Plain data written to bytes and read back in the same order: what a child process
// (base/ChildProcess.h) hands its parent. Counts precede their items; the reader checks every
// count against the bytes left, so a short or garbled message is an error, not a huge allocation.
#pragma once
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace tetglow {

class ByteWriter {
public:
    void add(const void* p, size_t n) { bytes_.append(static_cast<const char*>(p), n); }
    void add(uint64_t n) { add(&n, sizeof n); }
    void add(const std::string& s) {
        add(s.size());
        add(s.data(), s.size());
    }
    template <class T>
    void addItems(const T* items, size_t count) {
        add(uint64_t(count));
        add(items, count * sizeof(T));
    }
    template <class T>
    void add(const std::vector<T>& items) {
        addItems(items.data(), items.size());
    }
    void addStrings(const std::vector<std::string>& items) {
        add(items.size());
        for (const auto& s : items) add(s);
    }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
};

class ByteReader {
public:
    // `from`: whose message, for the error ("lost <from>'s answer").
    ByteReader(std::string bytes, std::string from) : bytes_(std::move(bytes)), from_(std::move(from)) {}
    void take(void* p, size_t n) {
        if (n > bytes_.size() - pos_) lost();
        if (n == 0) return;  // `p` may then be an empty vector's null data()
        std::memcpy(p, bytes_.data() + pos_, n);
        pos_ += n;
    }
    uint64_t number() {
        uint64_t n;
        take(&n, sizeof n);
        return n;
    }
    std::string string() {
        std::string s(count(1), '\0');
        take(s.data(), s.size());
        return s;
    }
    template <class T>
    std::vector<T> items() {
        std::vector<T> v(count(sizeof(T)));
        take(v.data(), v.size() * sizeof(T));
        return v;
    }
    std::vector<std::string> strings() {
        std::vector<std::string> v(count(sizeof(uint64_t)));
        for (auto& s : v) s = string();
        return v;
    }
    [[noreturn]] void lost() const { throw std::runtime_error("lost " + from_ + "'s answer"); }

private:
    uint64_t count(size_t itemBytes) {
        const uint64_t n = number();
        if (n > (bytes_.size() - pos_) / itemBytes) lost();
        return n;
    }
    std::string bytes_, from_;
    size_t pos_ = 0;
};

}  // namespace tetglow
