#pragma once
// Base64 (RFC 4648, standard alphabet, '=' padding) for data URIs.
#include <string>

namespace unimap::eval {

// The base64 text of bytes.
std::string EncodeBase64(const std::string& bytes);

}  // namespace unimap::eval
