MODULE string_literal_too_long
  ! Tests: a string literal longer than 80 characters is rejected before
  ! running (bad string, RMC103).
  PROC main()
    TPWrite "never printed";
    TPWrite "123456789012345678901234567890123456789012345678901234567890123456789012345678901";  ! <-- error
  ENDPROC
ENDMODULE
