MODULE Counter
    ! The operator adds parts from the FlexPendant; at two parts or more the
    ! lamp lights, the count is written out and starts again.
    VAR num count := 0;
    VAR bool full := FALSE;
    VAR num answer := 0;
    VAR signaldo lamp;
    CONST string config_lamp := "LAMP";

    PROC main()
        AliasIO config_lamp, lamp;
        WHILE TRUE DO
            TPReadNum answer, "How many parts?";
            Add answer;
        ENDWHILE
    ENDPROC

    PROC Add(num amount)
        count := count + amount;
        full := count >= 2;
        IF full THEN
            TPWrite "</script><b>full</b> at " \Num:=count;
            SetDO lamp, 1;
            count := 0;
        ELSE
            SetDO lamp, 0;
        ENDIF
    ENDPROC
ENDMODULE
