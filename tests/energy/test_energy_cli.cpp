// placeholder, filled with the CLI
#include <gtest/gtest.h>
