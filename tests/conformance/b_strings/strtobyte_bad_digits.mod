MODULE MainModule
  ! Tests: StrToByte of text that is not a valid byte in the chosen base is a recoverable
  ! run-time error (error number not asserted).
  PROC main()
    VAR byte b;
    b := StrToByte("G1" \Hex);
    TPWrite "not reached";
  ERROR
    TPWrite "error for G1";
  ENDPROC
ENDMODULE
