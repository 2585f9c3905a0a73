#include "whitted/render.hpp"

#include <gtest/gtest.h>

using namespace whitted;

TEST(Render, Placeholder) { SUCCEED(); }
