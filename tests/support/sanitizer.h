// TRACER_UNDER_ADDRESS_SANITIZER is 1 in an AddressSanitizer build (the sanitize preset):
// GCC defines __SANITIZE_ADDRESS__, clang 14 answers __has_feature(address_sanitizer).
#pragma once
#if defined(__SANITIZE_ADDRESS__)
#define TRACER_UNDER_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TRACER_UNDER_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef TRACER_UNDER_ADDRESS_SANITIZER
#define TRACER_UNDER_ADDRESS_SANITIZER 0
#endif
