MODULE VacuityTriggerNever
    ! count cycles through 0, 1, 2, so the request branch is dead code:
    ! request is never TRUE, and neither is served.
    VAR bool request := FALSE;
    VAR bool served := FALSE;
    VAR num count := 0;

    PROC main()
        WHILE TRUE DO
            count := (count + 1) MOD 3;
            IF count > 5 THEN
                request := TRUE;
            ENDIF
            served := request;
            request := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
