// Runs test code on a thread with a stack of a chosen size: the compilers' nesting limits are
// tested on an application worker's stack, and -- under the sanitizers, whose frames are several
// times larger (compiler/sanitizers.h) -- deep but legal input on a stack with room for them.
#pragma once

#include <gtest/gtest.h>
#include <pthread.h>

#include <cstddef>
#include <functional>

namespace pf::test {

// Runs `work` on a new thread whose stack is `bytes`, and waits for it.
inline void onStack(size_t bytes, const std::function<void()>& work) {
  pthread_attr_t attr;
  ASSERT_EQ(pthread_attr_init(&attr), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, bytes), 0);
  pthread_t thread;
  auto run = [](void* arg) -> void* {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attr, run, const_cast<std::function<void()>*>(&work)), 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
}

}  // namespace pf::test
