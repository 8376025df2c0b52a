MODULE MainModule
  ! Tests: NumToStr rounds to Dec decimals (manual example NumToStr(0.38521, 3) = "0.385").
  PROC main()
    TPWrite NumToStr(0.38521, 3);
    TPWrite NumToStr(0.38521, 1);
    TPWrite NumToStr(12, 0);
    TPWrite NumToStr(-3.14159, 2);
    TPWrite NumToStr(1234.5678, 1);
    TPWrite NumToStr(7.6, 0);
  ENDPROC
ENDMODULE
