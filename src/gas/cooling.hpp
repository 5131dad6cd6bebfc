// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The gas theory's interface is the installed header restitution/gas.hpp (the Python module binds it); this
// name stays for code written against the first version of the module.
#include "restitution/gas.hpp"
