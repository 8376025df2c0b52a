MODULE LoopRequestResponse
    ! Every request read from the configured input di_req is acknowledged.
    VAR bool request := FALSE;
    VAR bool ack := FALSE;

    PROC main()
        WHILE TRUE DO
            request := DInput(di_req) = 1;
            IF request THEN
                ack := TRUE;
                ack := FALSE;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
