MODULE GetDataValNotConfigured
    ! The operator may pick conveyor 3, whose signals EIO.cfg does not configure: the
    ! controller raises ERR_SYM_ACCESS at the GetDataVal, and nothing handles it.
    VAR signaldo doDrop;
    VAR num nCnv := 0;

    PROC main()
        TPReadFK nCnv, "Conveyor", "CNV1", "CNV2", "CNV3", "", "";
        GetDataVal "c" + ValToStr(nCnv) + "DropWObj", doDrop;
        PulseDO doDrop;
    ENDPROC
ENDMODULE
