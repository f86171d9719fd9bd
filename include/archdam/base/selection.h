#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace archdam
{
  /// The names of the choices of a selection, each with its enum value, in
  /// the order of the parameter's pattern. Each module keeps the list of its
  /// selections next to their enum, in its parameter header.
  template <typename Enum>
  using SelectionNames = std::vector<std::pair<std::string, Enum>>;

  /**
   * A parameter that selects one of a few named choices, bound to an enum:
   * the case file names the choice ("frictional contact"), the program sees
   * the enum (joints::Model::frictional_contact). The text is parsed once,
   * when the case is read, and the pattern (Selection of the names, in the
   * order given) rejects anything else with deal.II's message naming the
   * entry, so a misspelt choice can neither compile nor run. The default is
   * the name of @p value as it is when the parameter is declared.
   */
  template <typename Enum>
  void
  add_selection(dealii::ParameterHandler   &prm,
                const std::string          &entry,
                Enum                       &value,
                const SelectionNames<Enum> &names,
                const std::string          &documentation)
  {
    std::string pattern, default_name;
    for (const auto &[name, choice] : names)
      {
        pattern += (pattern.empty() ? "" : "|") + name;
        if (choice == value)
          default_name = name;
      }
    prm.declare_entry(entry, default_name, dealii::Patterns::Selection(pattern), documentation);
    prm.add_action(entry, [&value, names](const std::string &text) {
      for (const auto &[name, choice] : names)
        if (name == text)
          value = choice;
    });
  }

  /// The name of @p value among @p names (for messages and summaries).
  template <typename Enum>
  std::string
  selection_name(const Enum value, const SelectionNames<Enum> &names)
  {
    for (const auto &[name, choice] : names)
      if (choice == value)
        return name;
    return "";
  }

  /// The choice named @p text among @p names, or nothing if @p text names
  /// none of them (text that no Selection pattern has checked, such as a
  /// command-line option).
  template <typename Enum>
  std::optional<Enum>
  selection_value(const std::string &text, const SelectionNames<Enum> &names)
  {
    for (const auto &[name, choice] : names)
      if (name == text)
        return choice;
    return std::nullopt;
  }

  /// The names of @p names as a phrase: "a, b or c" (for messages).
  template <typename Enum>
  std::string
  selection_choices(const SelectionNames<Enum> &names)
  {
    std::string phrase;
    for (std::size_t i = 0; i < names.size(); ++i)
      phrase += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i].first;
    return phrase;
  }
} // namespace archdam
