#include "ceilplan/core/error.hpp"

#include <exception>

namespace ceilplan {

void rethrowWithContext(const std::string& context) {
  try {
    throw;
  } catch (const NoPathError& e) {
    throw NoPathError(context + e.what());
  } catch (const InfeasibleError& e) {
    throw InfeasibleError(context + e.what());
  } catch (const InputFileError& e) {
    throw InputFileError(context + e.what(), e.reason());
  } catch (const InputError& e) {
    throw InputError(context + e.what());
  } catch (const std::exception& e) {
    throw Error(context + e.what());
  }
}

}  // namespace ceilplan
