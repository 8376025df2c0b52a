MODULE MainModule
  ! Tests: NumToStr keeps Dec decimals even when they are zeros.
  ! FORMAT ASSUMPTION: undocumented; the reference recommends printf-style %.{Dec}f.
  PROC main()
    TPWrite NumToStr(2, 2);
    TPWrite NumToStr(0.5, 3);
  ENDPROC
ENDMODULE
