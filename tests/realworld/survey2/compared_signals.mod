MODULE ConveyorCell
  ! Signals of the I/O configuration read only in conditions, never declared
  VAR num nState := 0;
  PROC main()
    WHILE nState < 3 DO
      TEST nState
      CASE 0:
        SetDO DO_ENABLE_CONV, 1;
        nState := 1;
      CASE 1:
        IF DI_CONV_IN_POS = 1 THEN
          SetDO DO_ENABLE_CONV, 0;
          nState := 2;
        ENDIF
      CASE 2:
        IF giRecipe > 0 THEN
          TPWrite "recipe " \Num:=giRecipe;
        ENDIF
        nState := 3;
      ENDTEST
    ENDWHILE
  ENDPROC
ENDMODULE
