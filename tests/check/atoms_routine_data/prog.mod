MODULE RoutineData
    PROC main()
        VAR num count := 0;
        WHILE count < 3 DO
            count := count + 1;
        ENDWHILE
        Helper;
    ENDPROC

    PROC Helper()
        VAR bool inside := TRUE;
        inside := FALSE;
    ENDPROC
ENDMODULE
