/* QMC_API marks the functions of the C API (qmc.h), the only symbols the
 * shared library libqmc exports (CMake option QMC_SHARED). */
#ifndef QMC_EXPORT_H_
#define QMC_EXPORT_H_

#if defined(QMC_SHARED_LIBRARY)
#if defined(_WIN32)
#if defined(QMC_BUILDING_LIBRARY)
#define QMC_API __declspec(dllexport)
#else
#define QMC_API __declspec(dllimport)
#endif
#else
#define QMC_API __attribute__((visibility("default")))
#endif
#else
#define QMC_API
#endif

#endif /* QMC_EXPORT_H_ */
