MODULE Plc
    ! Written for the test: the PLC task only shows the station code's declaration; a PC
    ! writes the code.
    PERS num nStation := 0;
    VAR num shown := 0;

    PROC main()
        shown := nStation;
    ENDPROC
ENDMODULE
