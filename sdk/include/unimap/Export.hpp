#pragma once
// Symbol visibility: everything is hidden by default (-fvisibility=hidden);
// these macros mark what the shared libraries export.

#if defined(_WIN32)
#define UNIMAP_HELPER_EXPORT __declspec(dllexport)
#define UNIMAP_HELPER_IMPORT __declspec(dllimport)
#else
#define UNIMAP_HELPER_EXPORT __attribute__((visibility("default")))
#define UNIMAP_HELPER_IMPORT __attribute__((visibility("default")))
#endif

// Exported by libunimap_sdk.
#if defined(UNIMAP_SDK_BUILDING)
#define UNIMAP_SDK_API UNIMAP_HELPER_EXPORT
#else
#define UNIMAP_SDK_API UNIMAP_HELPER_IMPORT
#endif

// Exported by the core libraries (libunimap_config, ...).
#if defined(UNIMAP_CORE_BUILDING)
#define UNIMAP_CORE_API UNIMAP_HELPER_EXPORT
#else
#define UNIMAP_CORE_API UNIMAP_HELPER_IMPORT
#endif

// Exported by libunimap_conformance.
#if defined(UNIMAP_CONFORMANCE_BUILDING)
#define UNIMAP_CONFORMANCE_API UNIMAP_HELPER_EXPORT
#else
#define UNIMAP_CONFORMANCE_API UNIMAP_HELPER_IMPORT
#endif

// Exported by libunimap_mapper (the online mapper API).
#if defined(UNIMAP_MAPPER_BUILDING)
#define UNIMAP_MAPPER_API UNIMAP_HELPER_EXPORT
#else
#define UNIMAP_MAPPER_API UNIMAP_HELPER_IMPORT
#endif
