#include "model/BoundedCbor.h"

#include <string>

#include "base/Error.h"

namespace rigmesh::model {
namespace {

using nlohmann::json;
using DomParser = nlohmann::detail::json_sax_dom_parser<json>;

// The DOM builder, refusing to open one level more than the limit; the
// reader stops at once when a callback returns false (sax_parse is a
// template on the handler's type, so these hide the base's members).
class DepthLimitedParser : public DomParser {
  public:
    DepthLimitedParser(json& result, int maxDepth) : DomParser(result), maxDepth_(maxDepth) {}

    bool start_object(std::size_t length) { return enter() && DomParser::start_object(length); }
    bool end_object() {
        --depth_;
        return DomParser::end_object();
    }
    bool start_array(std::size_t length) { return enter() && DomParser::start_array(length); }
    bool end_array() {
        --depth_;
        return DomParser::end_array();
    }
    bool tooDeep() const { return tooDeep_; }

  private:
    bool enter() {
        tooDeep_ = ++depth_ > maxDepth_;
        return !tooDeep_;
    }
    int maxDepth_;
    int depth_ = 0;
    bool tooDeep_ = false;
};

}  // namespace

json parseBoundedCbor(const std::uint8_t* begin, const std::uint8_t* end, int maxDepth) {
    json result;
    DepthLimitedParser parser(result, maxDepth);
    json::sax_parse(begin, end, &parser, json::input_format_t::cbor);
    if (parser.tooDeep())
        throw Error(MessageId::DocumentNestedTooDeep, maxDepth);
    return result;
}

}  // namespace rigmesh::model
