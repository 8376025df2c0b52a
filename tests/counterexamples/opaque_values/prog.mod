MODULE OpaqueValues
    ! Data without a RAPID literal (rawbytes in a record, an array of syncident, a clock)
    ! next to value data; the counterexample names them by their type, never by Python's
    ! spelling of what rapidmc stores.
    RECORD packet
        num id;
        rawbytes data;
    ENDRECORD
    VAR syncident sync_ids{3};
    VAR packet pk;
    VAR clock timer;
    VAR num divisor := 0;

    PROC main()
        pk.id := 7;
        PackRawBytes 5, pk.data, 1 \IntX:=DINT;
        pk.id := pk.id / divisor;
    ENDPROC
ENDMODULE
