// No exception leaves the decoder's API (include/qmc/decoder.h). Built with
// exceptions, an allocation that fails is caught at the API boundary and
// reported; built without them (-fno-exceptions), nothing can throw and the
// limits of spec section 8.1 bound every allocation.
#pragma once

#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
#define QMC_TRY try
#define QMC_CATCH_ALL(handler) \
  catch (...) {                \
    handler;                   \
  }
#else
#define QMC_TRY if (true)
#define QMC_CATCH_ALL(handler) \
  else {                       \
    handler;                   \
  }
#endif
