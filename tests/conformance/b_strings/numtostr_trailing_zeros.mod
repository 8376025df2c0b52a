MODULE MainModule
  ! Tests: NumToStr does not pad with trailing zeros: NumToStr(2, 2) = "2".
  ! FORMAT ASSUMPTION: undocumented by ABB. Follows docs/semantics.md ("trailing zeros
  ! removed"); the reference (section 5.3) had suggested printf-style "%.{Dec}f" ("2.00").
  PROC main()
    TPWrite NumToStr(2, 2);
    TPWrite NumToStr(0.5, 3);
    TPWrite NumToStr(1.26, 1);
  ENDPROC
ENDMODULE
