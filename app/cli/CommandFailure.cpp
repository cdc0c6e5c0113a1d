#include "CommandFailure.h"

#include <new>

#include "base/Error.h"

namespace rigmesh::cli {

int reportFailure(const std::exception_ptr& thrown, std::FILE* out) {
    try {
        std::rethrow_exception(thrown);
    } catch (const Error& error) {
        std::fprintf(out, "rigmesh: %s\n", error.what());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        std::fprintf(out, "rigmesh: out of memory\n");
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::fprintf(out, "rigmesh: internal error: %s\n", error.what());
        return kExitInternalError;
    } catch (...) {
        std::fprintf(out, "rigmesh: internal error: an exception of unknown type\n");
        return kExitInternalError;
    }
}

}  // namespace rigmesh::cli
