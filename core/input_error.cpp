// SPDX-License-Identifier: MIT
#include "input_error.h"

namespace ab {

Refusal::Refusal(std::string_view sentence, std::vector<std::string> values, std::shared_ptr<const Refusal> inner)
    : text(sentence), args(std::move(values)), detail(std::move(inner))
{
}

std::string fillRefusal(std::string_view text, const std::vector<std::string>& args)
{
    std::string out;
    out.reserve(text.size() + 32);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (text[i] == '%' && next >= '1' && next <= '9') {
            const auto n = static_cast<std::size_t>(next - '1');
            out += n < args.size() ? args[n] : std::string(text.substr(i, 2));
            ++i;
        } else {
            out += text[i];
        }
    }
    return out;
}

std::string refusalMessage(const Refusal& r)
{
    if (!r.detail)
        return fillRefusal(r.text, r.args);
    std::vector<std::string> args = r.args;
    args.push_back(refusalMessage(*r.detail));
    return fillRefusal(r.text, args);
}

InputError::InputError(Refusal r)
    : std::runtime_error(refusalMessage(r)), refusal_(std::make_shared<const Refusal>(std::move(r)))
{
}

void refuse(std::string_view text, std::vector<std::string> args)
{
    throw InputError(Refusal{text, std::move(args)});
}

const std::vector<std::string_view>& refusalTexts()
{
    using namespace refusal;
    static const std::vector<std::string_view> texts{
        notANumber,      tooSmallForDouble, tooLargeForDouble, notFinite,       valueNotFinite, notWhole,
        wholeTooLarge,   beyondExact,       notVector,         notFiniteVector, outsideRange,   componentOutsideRange,
        outsideBox,      noRoomInBox,       stepNotPositive,   stepsOutside,    compareWith,    compareStart,
        streetTooNarrow, carsDoNotFit,      carsTooWide};
    return texts;
}

} // namespace ab
