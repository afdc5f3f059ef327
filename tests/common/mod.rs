pub mod line_oracle;
pub mod oracle;
