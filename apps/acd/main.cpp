// acd: command line for approximate convex decomposition (placeholder until the driver lands).
#include <cstdio>
int main() { std::puts("acd: under construction"); return 0; }
