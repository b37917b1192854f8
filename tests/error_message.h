#pragma once
// Test helper: the message of the exception of type Error that f() throws, "" if it throws none,
// so that a test asserts on the message itself. An exception of another type is not caught: the
// test fails on it, naming it.
#include <string>
#include <utility>

template <class Error, class F>
std::string message_of(F&& f) {
  try {
    std::forward<F>(f)();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
