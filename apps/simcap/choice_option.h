// An option whose word is one of a NameTable's names and whose value is the typed value it names,
// so that libraries receive enums, never text; a wrong word fails with
// "--name: unknown value 'word' (expected a, b or c)".
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/name_table.h"

namespace simcap::cli {

template <typename T, std::size_t N>
CLI::Option* add_choice(CLI::App* cmd, const std::string& flags, T& value,
                        const NameTable<T, N>& names, const std::string& help) {
  std::string list;
  for (const auto& [name, v] : names) list += (list.empty() ? "" : ",") + std::string(name);
  CLI::Validator known(
      [names](std::string& word) -> std::string {
        for (const auto& [name, v] : names) {
          if (word == name) return {};
        }
        return "unknown value '" + word + "' (expected " + choices_text(names) + ")";
      },
      "{" + list + "}");
  return cmd
      ->add_option_function<std::string>(
          flags,
          [&value, names](const std::string& word) {
            for (const auto& [name, v] : names) {
              if (word == name) value = v;
            }
          },
          help)
      ->check(known)
      ->default_str(std::string(name_of(names, value)));
}

}  // namespace simcap::cli
