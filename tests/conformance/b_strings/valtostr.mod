MODULE MainModule
  ! Tests: ValToStr writes a num with at most 6 significant digits (manual: 1.234567 -> "1.23457"),
  ! integers without decimals, a bool as TRUE/FALSE and a pos as an aggregate without spaces.
  PROC main()
    VAR pos p := [1817.3, 905.17, 879.11];
    TPWrite ValToStr(1.234567);
    TPWrite ValToStr(42);
    TPWrite ValToStr(-0.5);
    TPWrite ValToStr(TRUE);
    TPWrite ValToStr(p);
  ENDPROC
ENDMODULE
