#pragma once
// A run's failure, and the stability verdicts around it, in the window's language: simcore reports it in English (failure_texts.h, one
// place for every sentence); in another language the GUI says the same sentence with the same
// numbers, in the language's number format. A sentence it does not know (a SUNDIALS message)
// stays as it came.
#include <string>

#include <QString>

#include "simlab/stability.h"

namespace elui {

QString failureReason(const std::string& reason);
// simlab's stability sentences from their parts (English: simlab's own text): the verdict
// ("rk4 is stable up to DT = 0.00888 s on this body (exact spectrum, 96 eigenvalues)") and the
// pre-run advice ("dt = 0.03 s is above euler's largest stable step on this body, ...").
QString verdictSentence(const simlab::StabilityVerdict& verdict);
QString adviceSentence(const simlab::StabilityAdvice& advice);

}  // namespace elui
