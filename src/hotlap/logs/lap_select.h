#pragma once
/// @file
/// Keeping one lap's rows of a table with a `lap` column (a MoTeC export's, or a hotlap CSV's).

#include "hotlap/common/csv.h"

namespace hotlap {

/// Keeps the rows of `table` whose `lap` column is `lap`, in every column and in line_numbers.
/// Throws InputError naming the file when the table has no `lap` column, or when no row is lap
/// `lap` (the message lists the laps there are, e.g. "laps 1 to 3").
void SelectLap(CsvTable& table, int lap);

}  // namespace hotlap
