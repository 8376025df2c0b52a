MODULE MainModule
  ! Tests: TPReadNum shows its prompt as a line, then stores the operator's answer.
  PROC main()
    VAR num answer;
    TPReadNum answer, "How many parts?";
    TPWrite "answer=" \Num:=answer;
    TPWrite "double=" \Num:=answer * 2;
  ENDPROC
ENDMODULE
