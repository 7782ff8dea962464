/* SHA-256 (FIPS 180-4) in C, for checking canonical outputs against the
 * conformance manifest without anything but qmc.h and the C library. */
#ifndef QMC_TESTS_CAPI_SHA256_H_
#define QMC_TESTS_CAPI_SHA256_H_

#include <stddef.h>
#include <stdint.h>

/* Writes the 64 lowercase hex digits of SHA-256(data) and a NUL to hex. */
void sha256_hex(const uint8_t* data, size_t size, char hex[65]);

#endif
