#pragma once
// Explicit instantiation lists: X(D) for every dimension a dimension-generic
// sampler or analysis is built for (kMinDim to kMaxDim in point.h).
#define PDS_FOR_EACH_DIM(X) X(1) X(2) X(3) X(4) X(5) X(6) X(7) X(8)
