MODULE MainModule
  ! Tests: StrMap replaces each character found at position k of FromMap by ToMap's k-th
  ! character; other characters are kept.
  PROC main()
    TPWrite StrMap("Robotics", "aeiou", "AEIOU");
    TPWrite StrMap("Robotics", STR_LOWER, STR_UPPER);
    TPWrite StrMap("a-b-c", "-", "_");
  ENDPROC
ENDMODULE
