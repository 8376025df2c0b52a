MODULE diagnose_codes
    ! Survey round 7: command codes read as components of a record of a module that was
    ! not given (a scalar, not an array), and passed to a routine of that module.
    PERS num nAsked := 0;

    PROC main()
        AskCell(cmdCodes.READ_TIME);
        nAsked := nAsked + 1;
        AskCell(cmdCodes.READ_PART);
        nAsked := nAsked + 1;
    ENDPROC
ENDMODULE
