MODULE Motion
    ! The flag, the command index and the state come from a socket task that is not
    ! loaded; 'rapidmc stubs' declared them (Missing.mod). The flag is polled and cleared;
    ! the state is passed on to a routine that compares it with 1 and 2, so those values
    ! are tried: every line is reached.
    VAR num moved := 0;

    PROC main()
        WHILE TRUE DO
            IF newTargetFlag = TRUE THEN
                newTargetFlag := FALSE;
                IF smIndx = "d" Run stateChoice;
            ENDIF
            WaitTime 0.25;
        ENDWHILE
    ENDPROC

    PROC Run(num state)
        moved := Pick(state);
    ENDPROC

    FUNC num Pick(num which)
        TEST which
        CASE 1:
            RETURN 10;
        CASE 2:
            RETURN 20;
        ENDTEST
        RETURN 0;
    ENDFUNC
ENDMODULE
