this is not a shader at all
