MODULE Rob2
  PERS bool bTurn := TRUE;
  VAR jointtarget jpos;
  PROC main()
    WHILE TRUE DO
      WaitUntil NOT bTurn;
      jpos := CJointT();
      jpos.robax.rax_1 := jpos.robax.rax_1 + 90;
      MoveAbsJ jpos, v100, fine, tool0;
      bTurn := TRUE;
    ENDWHILE
  ENDPROC
ENDMODULE
