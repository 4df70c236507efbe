//! algebra! proc-macro
