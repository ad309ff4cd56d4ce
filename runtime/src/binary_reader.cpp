#include "binary_reader.hpp"
// The reader is header-only; this unit keeps the library's file list honest.
