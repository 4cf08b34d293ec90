// Accepted forms (verif/hls_subset/README.md): a *_tables.hpp header (constants and ROM contents)
// needs no top function.
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kAcceptedTableSize = 4;
constexpr unsigned kAcceptedGains[kAcceptedTableSize] = {1u, 2u, 4u, 0x8u};

CIG_HLS_END_NAMESPACE
