MODULE MainModule
  ! Tests: StrPart(Str, ChPos, Len) takes Len characters from 1-based ChPos (manual: "Robot").
  PROC main()
    TPWrite StrPart("Robotics", 1, 5);
    TPWrite StrPart("Robotics", 6, 3);
    TPWrite StrPart("Robotics", 8, 1);
  ENDPROC
ENDMODULE
